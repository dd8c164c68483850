!> Zoning of one block polygon into constant-strain triangles (manual
!> Section 4.5 GENERATE, Section 3.2 Fig 3-3c). Pure geometry: the input is
!> a clockwise corner ring, the output a `mesh_t` whose first `nb` points are
!> the new boundary ring (clockwise, starting at the ring's first corner,
!> original corners plus points added on the edges) followed by interior
!> points, and counter-clockwise triangles on those points. Applying a mesh
!> to the model is zones_generate's job. docs/zones.md describes the
!> algorithms and the quality measured.
!>
!> AUTO (EDGE) edmax: every edge is split into equal pieces <= edmax; the
!> corner polygon is ear-clipped, the edge points are inserted on the
!> boundary, interior points of a hexagonal lattice of spacing edmax (at
!> least edmax/2 from the boundary) are inserted with Lawson flips (a
!> constrained Delaunay triangulation, the constraints being the block
!> boundary), then Delaunay refinement (Ruppert): encroached boundary
!> pieces are halved, triangles with an angle below `target_angle` or an
!> edge above edmax get their circumcentre. A block with no lattice point is
!> zoned on its centroid, and kept so when those zones meet the targets (the
!> 1989 AUTO split edges by length alone: docs/zones.md). Corners sharper than 60 degrees
!> are protected from endless refinement (no ping-pong between their two
!> edges). Last, interior points are smoothed (Laplacian, a move is kept
!> only if the smallest angle around the point does not drop) and edges
!> are flipped back to Delaunay (which never lowers the smallest angle).
!>
!> The pieces: zones_mesh_base (mesh_t, queries), zones_triangulation,
!> zones_refinement, zones_mesh_quad, zones_mesh_manual; this module is the
!> AUTO driver and the one place callers import from.
module zones_mesh
   use core_arrays, only: push_back
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use core_constants, only: pi
   use geometry_polygon, only: point_in_polygon, polygon_boundary_distance
   use zones_triangulation, only: tri_t, tri_alloc, add_vertex, ear_clip, lawson, &
                                  insert_point, export, edge_len, quality
   use zones_refinement, only: insert_lattice, refine, smooth
   use zones_mesh_base, only: mesh_t, mesh_min_angle, mesh_area, mesh_target_angle, &
                              mesh_sharpest_zone, mesh_smallest_zone
   use zones_mesh_quad, only: mesh_quad
   use zones_mesh_manual, only: mesh_manual
   implicit none
   private
   public :: mesh_t, mesh_auto, mesh_quad, mesh_manual, mesh_min_angle, mesh_area
   public :: mesh_sharpest_zone, mesh_smallest_zone
   public :: mesh_target_angle

contains

   !> Triangulate the clockwise polygon x, y with zone edges <= edmax.
   subroutine mesh_auto(x, y, edmax, mesh, error)
      real(wp), intent(in) :: x(:), y(:), edmax
      type(mesh_t), intent(out) :: mesh
      type(error_t), allocatable, intent(out) :: error
      type(tri_t) :: tr
      integer(ip) :: n, k, j, m, t, i, st, nlat, maxv
      real(wp) :: len, px, py, h, xc, yc, a
      integer(ip), allocatable :: stack(:)
      integer(ip) :: ns

      n = size(x)
      if (n < 3) then
         call set_error(error, 'fewer than 3 corners')
         return
      end if
      if (.not. edmax > 0.0_wp) then
         call set_error(error, 'the maximum zone edge must be positive')
         return
      end if
      tr%ncorner = n
      tr%scale = max(maxval(x) - minval(x), maxval(y) - minval(y))
      call tri_alloc(tr, 4*n + 64)
      do k = 1, n
         call add_vertex(tr, x(k), y(k), 1, k, j)
      end do
      allocate (tr%sharp(n))
      do k = 1, n
         tr%sharp(k) = interior_angle(x, y, k) < pi/3.0_wp
      end do
      call ear_clip(tr, error)
      if (allocated(error)) return
      allocate (stack(64))
      ns = 0
      do t = 1, tr%nt
         call push_back(stack, ns, t)
      end do
      call lawson(tr, stack, ns)
      ! edge points
      do k = 1, n
         j = merge(1_ip, k + 1, k == n)
         len = hypot(x(j) - x(k), y(j) - y(k))
         m = max(1_ip, ceiling(len/edmax - 1.0e-9_wp, ip))
         do i = 1, m - 1
            px = x(k) + (x(j) - x(k))*real(i, wp)/real(m, wp)
            py = y(k) + (y(j) - y(k))*real(i, wp)/real(m, wp)
            call insert_point(tr, px, py, 2, k, tr%vtri(k), st)
         end do
      end do
      ! interior lattice
      h = edmax
      call insert_lattice(tr, x, y, h, nlat)
      if (nlat == 0) then
         ! small block: a gridpoint at the centroid if it sits well inside
         call centroid_of(x, y, xc, yc, a)
         if (point_in_polygon(x, y, xc, yc)) then
            if (polygon_boundary_distance(x, y, xc, yc) >= 0.2_wp*longest_edge(tr)) then
               call insert_point(tr, xc, yc, 0, 0, 1_ip, st)
               ! zones on the centre that meet the angle and length targets are
               ! the mesh: the 1989 AUTO split block edges by length alone, and
               ! refinement would halve every edge whose diametral circle holds
               ! the centre, as the long edges of an oblong block (docs/zones.md)
               if (all_good(tr, edmax)) then
                  call export(tr, mesh)
                  return
               end if
            end if
         end if
      end if
      maxv = 4*tr%nv + 4000
      call refine(tr, edmax, maxv)
      call smooth(tr, 3, edmax)
      ns = 0
      do t = 1, tr%nt
         call push_back(stack, ns, t)
      end do
      call lawson(tr, stack, ns)
      ! flips may have made an edge longer than edmax or an angle smaller
      call refine(tr, edmax, maxv + 4*tr%nv)
      call export(tr, mesh)
   end subroutine mesh_auto

   !> Interior angle at corner k of a clockwise polygon, in (0, 2 pi).
   pure real(wp) function interior_angle(x, y, k) result(theta)
      real(wp), intent(in) :: x(:), y(:)
      integer(ip), intent(in) :: k
      integer(ip) :: p, q, n
      n = size(x)
      p = merge(n, k - 1, k == 1)
      q = merge(1_ip, k + 1, k == n)
      theta = modulo(atan2(y(q) - y(k), x(q) - x(k)) - atan2(y(p) - y(k), x(p) - x(k)), &
                     2.0_wp*pi)
   end function interior_angle

   pure subroutine centroid_of(x, y, xc, yc, a)
      real(wp), intent(in) :: x(:), y(:)
      real(wp), intent(out) :: xc, yc, a
      integer(ip) :: i, j, n
      real(wp) :: cr
      n = size(x)
      a = 0.0_wp; xc = 0.0_wp; yc = 0.0_wp
      do i = 1, n
         j = merge(1_ip, i + 1, i == n)
         cr = (x(i) - x(1))*(y(j) - y(1)) - (x(j) - x(1))*(y(i) - y(1))
         a = a + cr
         xc = xc + (x(i) + x(j) - 2.0_wp*x(1))*cr
         yc = yc + (y(i) + y(j) - 2.0_wp*y(1))*cr
      end do
      if (a /= 0.0_wp) then
         xc = x(1) + xc/(3.0_wp*a)
         yc = y(1) + yc/(3.0_wp*a)
      else
         xc = sum(x)/n; yc = sum(y)/n
      end if
      a = 0.5_wp*a
   end subroutine centroid_of

   !> Every triangle has its smallest angle >= mesh_target_angle and its
   !> edges <= edmax (the refinement's targets and tolerance).
   logical function all_good(tr, edmax) result(ok)
      type(tri_t), intent(in) :: tr
      real(wp), intent(in) :: edmax
      integer(ip) :: t, imin
      real(wp) :: q, lmax, lmin
      ok = .true.
      do t = 1, tr%nt
         call quality(tr, t, q, lmax, lmin, imin)
         if (q < sin(mesh_target_angle*pi/180.0_wp) .or. lmax > edmax*(1.0_wp + 1.0e-6_wp)) then
            ok = .false.
            return
         end if
      end do
   end function all_good

   real(wp) function longest_edge(tr) result(l)
      type(tri_t), intent(in) :: tr
      integer(ip) :: t, i
      l = 0.0_wp
      do t = 1, tr%nt
         do i = 1, 3
            l = max(l, edge_len(tr, t, i))
         end do
      end do
   end function longest_edge

end module zones_mesh
