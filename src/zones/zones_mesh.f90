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
!> edge above edmax get their circumcentre. Corners sharper than 60 degrees
!> are protected from endless refinement (no ping-pong between their two
!> edges). Last, interior points are smoothed (Laplacian, a move is kept
!> only if the smallest angle around the point does not drop) and edges
!> are flipped back to Delaunay (which never lowers the smallest angle).
module zones_mesh
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use core_output, only: format_real, fmt_real
   use geometry_polygon, only: point_in_polygon, polygon_boundary_distance, &
                            polygon_signed_area, segment_distance, pi
   implicit none
   private
   public :: mesh_t, mesh_auto, mesh_quad, mesh_manual, mesh_min_angle, mesh_area
   public :: mesh_target_angle

   !> Smallest zone angle Delaunay refinement aims at (degrees).
   real(wp), parameter :: mesh_target_angle = 25.0_wp

   type :: mesh_t
      integer(ip) :: nb = 0                     !< boundary ring points (first nb)
      integer(ip) :: np = 0                     !< all points
      real(wp), allocatable :: x(:), y(:)
      integer(ip), allocatable :: orig(:)       !< ring point: index of the input corner, or 0
      integer(ip) :: nt = 0
      integer(ip), allocatable :: tri(:, :)     !< (3, nt), counter-clockwise
   end type mesh_t

   !> Working triangulation. Triangle t has vertices v(1:3,t) counter-
   !> clockwise; n(i,t) is the triangle across the edge opposite v(i,t)
   !> (0: block boundary). Vertex kind: 0 interior, 1 input corner (seg =
   !> corner index), 2 on input edge seg (from corner seg to seg+1).
   type :: tri_t
      integer(ip) :: nv = 0, nt = 0, ncorner = 0
      real(wp), allocatable :: x(:), y(:)
      integer(ip), allocatable :: kind(:), seg(:), vtri(:)
      integer(ip), allocatable :: v(:, :), n(:, :)
      logical, allocatable :: sharp(:)          !< input corner below 60 degrees
      integer(ip) :: walk_seed = 0
      real(wp) :: scale = 1.0_wp                !< length scale for tolerances
   end type tri_t

   integer, parameter :: loc_inside = 1, loc_edge = 2, loc_outside = 3, loc_failed = 4

contains

   ! ------------------------------------------------------------------ AUTO

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
         call push(stack, ns, t)
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
            if (polygon_boundary_distance(x, y, xc, yc) >= 0.2_wp*longest_edge(tr)) &
               call insert_point(tr, xc, yc, 0, 0, 1_ip, st)
         end if
      end if
      maxv = 4*tr%nv + 4000
      call refine(tr, edmax, maxv)
      call smooth(tr, 3, edmax)
      ns = 0
      do t = 1, tr%nt
         call push(stack, ns, t)
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

   !> Hexagonal lattice of spacing h, points at least h/2 inside the
   !> boundary, inserted row by row in snake order (short walks).
   subroutine insert_lattice(tr, x, y, h, count)
      type(tri_t), intent(inout) :: tr
      real(wp), intent(in) :: x(:), y(:), h
      integer(ip), intent(out) :: count
      real(wp) :: xmin, xmax, ymin, ymax, dy, y0, x0, yr, xs(size(x) + 2), dmin, px, d, t
      real(wp) :: tmp
      integer(ip) :: nrow, ncol, r, n, i, j, nx, c, k, st, last, c0, c1, dc
      logical :: ok
      count = 0
      n = size(x)
      xmin = minval(x); xmax = maxval(x); ymin = minval(y); ymax = maxval(y)
      dy = h*sqrt(3.0_wp)/2.0_wp
      dmin = 0.5_wp*h
      if (ymax - ymin < 2.0_wp*dmin .or. xmax - xmin < 2.0_wp*dmin) return
      nrow = int((ymax - ymin)/dy) + 1
      y0 = ymin + 0.5_wp*((ymax - ymin) - real(nrow - 1, wp)*dy)
      ncol = int((xmax - xmin)/h) + 2
      x0 = xmin + 0.5_wp*((xmax - xmin) - real(ncol - 1, wp)*h) - 0.25_wp*h
      last = tr%vtri(1)
      do r = 0, nrow - 1
         yr = y0 + real(r, wp)*dy
         ! crossings of the row with the boundary
         nx = 0
         j = n
         do i = 1, n
            if ((y(i) > yr) .neqv. (y(j) > yr)) then
               nx = nx + 1
               xs(nx) = x(i) + (yr - y(i))*(x(j) - x(i))/(y(j) - y(i))
            end if
            j = i
         end do
         do i = 2, nx
            tmp = xs(i)
            k = i - 1
            do while (k >= 1)
               if (xs(k) <= tmp) exit
               xs(k + 1) = xs(k)
               k = k - 1
            end do
            xs(k + 1) = tmp
         end do
         if (mod(r, 2_ip) == 0) then
            c0 = 0; c1 = ncol; dc = 1
         else
            c0 = ncol; c1 = 0; dc = -1
         end if
         do c = c0, c1, dc
            px = x0 + real(c, wp)*h + merge(0.5_wp*h, 0.0_wp, mod(r, 2_ip) == 1)
            ok = .false.
            do k = 1, nx - 1, 2
               if (px > xs(k) + dmin .and. px < xs(k + 1) - dmin) ok = .true.
            end do
            if (.not. ok) cycle
            ! distance to every edge near the row
            j = n
            do i = 1, n
               if (min(y(i), y(j)) < yr + dmin .and. max(y(i), y(j)) > yr - dmin) then
                  call segment_distance(px, yr, x(j), y(j), x(i), y(i), d, t)
                  if (d < dmin) then
                     ok = .false.
                     exit
                  end if
               end if
               j = i
            end do
            if (.not. ok) cycle
            call insert_point(tr, px, yr, 0, 0, last, st)
            if (st == loc_inside .or. st == loc_edge) then
               count = count + 1
               last = tr%vtri(tr%nv)
            end if
         end do
      end do
   end subroutine insert_lattice

   ! ------------------------------------------------------- triangulation

   subroutine tri_alloc(tr, m)
      type(tri_t), intent(inout) :: tr
      integer(ip), intent(in) :: m
      allocate (tr%x(m), tr%y(m), tr%kind(m), tr%seg(m), tr%vtri(m))
      allocate (tr%v(3, 2*m), tr%n(3, 2*m))
   end subroutine tri_alloc

   subroutine add_vertex(tr, px, py, kind, seg, id)
      type(tri_t), intent(inout) :: tr
      real(wp), intent(in) :: px, py
      integer(ip), intent(in) :: kind, seg
      integer(ip), intent(out) :: id
      real(wp), allocatable :: r(:)
      integer(ip), allocatable :: iv(:)
      integer(ip) :: m
      if (tr%nv >= size(tr%x)) then
         m = 2*size(tr%x)
         allocate (r(m)); r(1:tr%nv) = tr%x(1:tr%nv); call move_alloc(r, tr%x)
         allocate (r(m)); r(1:tr%nv) = tr%y(1:tr%nv); call move_alloc(r, tr%y)
         allocate (iv(m)); iv(1:tr%nv) = tr%kind(1:tr%nv); call move_alloc(iv, tr%kind)
         allocate (iv(m)); iv(1:tr%nv) = tr%seg(1:tr%nv); call move_alloc(iv, tr%seg)
         allocate (iv(m)); iv(1:tr%nv) = tr%vtri(1:tr%nv); call move_alloc(iv, tr%vtri)
      end if
      tr%nv = tr%nv + 1
      id = tr%nv
      tr%x(id) = px
      tr%y(id) = py
      tr%kind(id) = kind
      tr%seg(id) = seg
      tr%vtri(id) = 0
   end subroutine add_vertex

   subroutine new_triangle(tr, t)
      type(tri_t), intent(inout) :: tr
      integer(ip), intent(out) :: t
      integer(ip), allocatable :: a(:, :)
      integer(ip) :: m
      if (tr%nt >= size(tr%v, 2)) then
         m = 2*size(tr%v, 2)
         allocate (a(3, m)); a(:, 1:tr%nt) = tr%v(:, 1:tr%nt); call move_alloc(a, tr%v)
         allocate (a(3, m)); a(:, 1:tr%nt) = tr%n(:, 1:tr%nt); call move_alloc(a, tr%n)
      end if
      tr%nt = tr%nt + 1
      t = tr%nt
   end subroutine new_triangle

   subroutine set_tri(tr, t, a, b, c, na, nb, nc)
      type(tri_t), intent(inout) :: tr
      integer(ip), intent(in) :: t, a, b, c, na, nb, nc
      tr%v(:, t) = [a, b, c]
      tr%n(:, t) = [na, nb, nc]
      tr%vtri(a) = t
      tr%vtri(b) = t
      tr%vtri(c) = t
   end subroutine set_tri

   !> In triangle w (if any) the neighbour `old` becomes `new`.
   subroutine replace_nb(tr, w, old, new)
      type(tri_t), intent(inout) :: tr
      integer(ip), intent(in) :: w, old, new
      integer :: k
      if (w == 0) return
      do k = 1, 3
         if (tr%n(k, w) == old) then
            tr%n(k, w) = new
            return
         end if
      end do
   end subroutine replace_nb

   pure integer(ip) function nxt(i)
      integer(ip), intent(in) :: i
      nxt = merge(1_ip, i + 1, i == 3)
   end function nxt

   pure integer(ip) function prv(i)
      integer(ip), intent(in) :: i
      prv = merge(3_ip, i - 1, i == 1)
   end function prv

   pure real(wp) function orient(ax, ay, bx, by, cx, cy)
      real(wp), intent(in) :: ax, ay, bx, by, cx, cy
      orient = (bx - ax)*(cy - ay) - (by - ay)*(cx - ax)
   end function orient

   !> > 0 when d is inside the circumcircle of counter-clockwise a b c.
   pure real(wp) function incircle(ax, ay, bx, by, cx, cy, dx, dy)
      real(wp), intent(in) :: ax, ay, bx, by, cx, cy, dx, dy
      real(wp) :: adx, ady, bdx, bdy, cdx, cdy
      adx = ax - dx; ady = ay - dy
      bdx = bx - dx; bdy = by - dy
      cdx = cx - dx; cdy = cy - dy
      incircle = (adx*adx + ady*ady)*(bdx*cdy - cdx*bdy) &
                 - (bdx*bdx + bdy*bdy)*(adx*cdy - cdx*ady) &
                 + (cdx*cdx + cdy*cdy)*(adx*bdy - bdx*ady)
   end function incircle

   real(wp) function edge_len(tr, t, i)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: t, i
      integer(ip) :: a, b
      a = tr%v(nxt(i), t)
      b = tr%v(prv(i), t)
      edge_len = hypot(tr%x(b) - tr%x(a), tr%y(b) - tr%y(a))
   end function edge_len

   !> Ear clipping of the input corner polygon (vertices 1..ncorner, clockwise).
   subroutine ear_clip(tr, error)
      type(tri_t), intent(inout) :: tr
      type(error_t), allocatable, intent(out) :: error
      integer(ip) :: n, left, v, p, q, k, w, guard, t, a, b, i, j
      integer(ip), allocatable :: nx(:), pv(:), adj_start(:), adj(:), cnt(:)
      logical, allocatable :: convex(:), gone(:)
      logical :: ear
      real(wp) :: eps
      n = tr%ncorner
      allocate (nx(n), pv(n), convex(n), gone(n))
      ! counter-clockwise ring = reverse of the clockwise input
      do k = 1, n
         nx(k) = merge(n, k - 1, k == 1)
         pv(k) = merge(1_ip, k + 1, k == n)
      end do
      gone = .false.
      eps = 1.0e-12_wp*tr%scale**2
      do k = 1, n
         convex(k) = orient(tr%x(pv(k)), tr%y(pv(k)), tr%x(k), tr%y(k), tr%x(nx(k)), &
                            tr%y(nx(k))) > eps
      end do
      left = n
      v = 1
      guard = 0
      do while (left > 3)
         guard = guard + 1
         if (guard > 4*n*n + 100) then
            call set_error(error, 'the block boundary could not be triangulated')
            return
         end if
         p = pv(v); q = nx(v)
         ear = convex(v)
         if (ear) then
            w = nx(q)
            do while (w /= p)
               if (.not. convex(w)) then
                  if (in_closed_triangle(w)) then
                     ear = .false.
                     exit
                  end if
               end if
               w = nx(w)
            end do
         end if
         if (ear) then
            call new_triangle(tr, t)
            tr%v(:, t) = [p, v, q]
            nx(p) = q
            pv(q) = p
            gone(v) = .true.
            left = left - 1
            convex(p) = orient(tr%x(pv(p)), tr%y(pv(p)), tr%x(p), tr%y(p), tr%x(nx(p)), &
                               tr%y(nx(p))) > eps
            convex(q) = orient(tr%x(pv(q)), tr%y(pv(q)), tr%x(q), tr%y(q), tr%x(nx(q)), &
                               tr%y(nx(q))) > eps
            v = p
            guard = 0
         else
            v = q
         end if
      end do
      v = 1
      do while (gone(v))
         v = v + 1
      end do
      call new_triangle(tr, t)
      tr%v(:, t) = [pv(v), v, nx(v)]
      if (orient(tr%x(pv(v)), tr%y(pv(v)), tr%x(v), tr%y(v), tr%x(nx(v)), tr%y(nx(v))) <= 0) &
         then
         call set_error(error, 'the block boundary could not be triangulated')
         return
      end if
      ! neighbours through the triangles of each vertex
      allocate (cnt(n + 1), adj_start(n + 1), adj(3*tr%nt))
      cnt = 0
      do t = 1, tr%nt
         do i = 1, 3
            cnt(tr%v(i, t)) = cnt(tr%v(i, t)) + 1
         end do
      end do
      adj_start(1) = 1
      do k = 1, n
         adj_start(k + 1) = adj_start(k) + cnt(k)
      end do
      cnt = 0
      do t = 1, tr%nt
         do i = 1, 3
            k = tr%v(i, t)
            adj(adj_start(k) + cnt(k)) = t
            cnt(k) = cnt(k) + 1
            tr%vtri(k) = t
         end do
      end do
      tr%n(:, 1:tr%nt) = 0
      do t = 1, tr%nt
         do i = 1, 3
            a = tr%v(nxt(i), t)
            b = tr%v(prv(i), t)
            do k = adj_start(a), adj_start(a + 1) - 1
               w = adj(k)
               if (w == t) cycle
               do j = 1, 3
                  if (tr%v(j, w) == b .and. tr%v(nxt(j), w) == a) tr%n(i, t) = w
               end do
            end do
         end do
      end do
   contains
      logical function in_closed_triangle(w_)
         integer(ip), intent(in) :: w_
         real(wp) :: o1, o2, o3
         o1 = orient(tr%x(p), tr%y(p), tr%x(v), tr%y(v), tr%x(w_), tr%y(w_))
         o2 = orient(tr%x(v), tr%y(v), tr%x(q), tr%y(q), tr%x(w_), tr%y(w_))
         o3 = orient(tr%x(q), tr%y(q), tr%x(p), tr%y(p), tr%x(w_), tr%y(w_))
         in_closed_triangle = o1 >= -eps .and. o2 >= -eps .and. o3 >= -eps
      end function in_closed_triangle
   end subroutine ear_clip

   subroutine push(stack, ns, t)
      integer(ip), allocatable, intent(inout) :: stack(:)
      integer(ip), intent(inout) :: ns
      integer(ip), intent(in) :: t
      integer(ip), allocatable :: tmp(:)
      if (ns >= size(stack)) then
         allocate (tmp(2*size(stack)))
         tmp(1:ns) = stack(1:ns)
         call move_alloc(tmp, stack)
      end if
      ns = ns + 1
      stack(ns) = t
   end subroutine push

   !> Flip the edge opposite v(i,t); afterwards t = (a, b, d), u = (a, d, c)
   !> where a = old v(i,t), so a stays vertex 1 of both.
   subroutine flip(tr, t, i)
      type(tri_t), intent(inout) :: tr
      integer(ip), intent(in) :: t, i
      integer(ip) :: a, b, c, d, u, j, nca, nab, nbd, ndc
      a = tr%v(i, t); b = tr%v(nxt(i), t); c = tr%v(prv(i), t)
      u = tr%n(i, t)
      nca = tr%n(nxt(i), t)
      nab = tr%n(prv(i), t)
      do j = 1, 3
         if (tr%v(j, u) /= b .and. tr%v(j, u) /= c) exit
      end do
      d = tr%v(j, u)
      ! u = (d, c, b): opposite c is edge b-d, opposite b is edge d-c
      nbd = tr%n(nxt(j), u)
      ndc = tr%n(prv(j), u)
      call set_tri(tr, t, a, b, d, nbd, u, nab)
      call set_tri(tr, u, a, d, c, ndc, nca, t)
      call replace_nb(tr, nbd, u, t)
      call replace_nb(tr, nca, t, u)
   end subroutine flip

   !> True when the edge opposite v(i,t) may be flipped to improve Delaunay-ness.
   logical function should_flip(tr, t, i)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: t, i
      integer(ip) :: a, b, c, d, u, j
      real(wp) :: s2
      should_flip = .false.
      u = tr%n(i, t)
      if (u == 0) return
      a = tr%v(i, t); b = tr%v(nxt(i), t); c = tr%v(prv(i), t)
      do j = 1, 3
         if (tr%v(j, u) /= b .and. tr%v(j, u) /= c) exit
      end do
      d = tr%v(j, u)
      s2 = max((tr%x(a) - tr%x(d))**2 + (tr%y(a) - tr%y(d))**2, &
               (tr%x(b) - tr%x(d))**2 + (tr%y(b) - tr%y(d))**2, &
               (tr%x(c) - tr%x(d))**2 + (tr%y(c) - tr%y(d))**2)
      if (incircle(tr%x(a), tr%y(a), tr%x(b), tr%y(b), tr%x(c), tr%y(c), tr%x(d), tr%y(d)) &
          <= 1.0e-10_wp*s2*s2) return
      ! the quadrilateral a b d c must be strictly convex
      if (orient(tr%x(a), tr%y(a), tr%x(b), tr%y(b), tr%x(d), tr%y(d)) <= 0.0_wp) return
      if (orient(tr%x(a), tr%y(a), tr%x(d), tr%y(d), tr%x(c), tr%y(c)) <= 0.0_wp) return
      should_flip = .true.
   end function should_flip

   !> Flip non-Delaunay edges of the triangles on the stack until none is left.
   subroutine lawson(tr, stack, ns)
      type(tri_t), intent(inout) :: tr
      integer(ip), allocatable, intent(inout) :: stack(:)
      integer(ip), intent(inout) :: ns
      integer(ip) :: t, i, u, nflip
      nflip = 0
      do while (ns > 0)
         t = stack(ns)
         ns = ns - 1
         do i = 1, 3
            if (should_flip(tr, t, i)) then
               u = tr%n(i, t)
               call flip(tr, t, i)
               nflip = nflip + 1
               call push(stack, ns, t)
               call push(stack, ns, u)
               exit
            end if
         end do
         if (nflip > 50*(tr%nt + 100)) exit     ! round-off guard
      end do
      ns = 0
   end subroutine lawson

   !> Find the triangle containing (px, py) by walking from `start`.
   subroutine locate(tr, px, py, start, t, i, status)
      type(tri_t), intent(inout) :: tr
      real(wp), intent(in) :: px, py
      integer(ip), intent(in) :: start
      integer(ip), intent(out) :: t, i, status
      integer(ip) :: steps, k, kk, best
      real(wp) :: o, eps, ob, l2
      t = start
      if (t < 1 .or. t > tr%nt) t = 1
      do steps = 1, 4*tr%nt + 100
         best = 0
         ob = 0.0_wp
         tr%walk_seed = modulo(tr%walk_seed + 1, 3_ip)
         do kk = 0, 2
            k = 1 + modulo(tr%walk_seed + kk, 3_ip)
            associate (a => tr%v(nxt(k), t), b => tr%v(prv(k), t))
               o = orient(tr%x(a), tr%y(a), tr%x(b), tr%y(b), px, py)
               l2 = (tr%x(b) - tr%x(a))**2 + (tr%y(b) - tr%y(a))**2
            end associate
            eps = 1.0e-11_wp*l2
            if (o < -eps) then
               best = k
               exit
            else if (abs(o) <= eps) then
               ob = real(k, wp)
            end if
         end do
         if (best == 0) then
            if (ob > 0.0_wp) then
               i = int(ob, ip)
               status = loc_edge
            else
               i = 0
               status = loc_inside
            end if
            return
         end if
         if (tr%n(best, t) == 0) then
            i = best
            status = loc_outside
            return
         end if
         t = tr%n(best, t)
      end do
      ! the walk did not converge (round-off): search every triangle
      do t = 1, tr%nt
         kk = 0
         do k = 1, 3
            associate (a => tr%v(nxt(k), t), b => tr%v(prv(k), t))
               o = orient(tr%x(a), tr%y(a), tr%x(b), tr%y(b), px, py)
               l2 = (tr%x(b) - tr%x(a))**2 + (tr%y(b) - tr%y(a))**2
            end associate
            if (o < -1.0e-11_wp*l2) kk = -1
         end do
         if (kk == 0) then
            i = 0
            status = loc_inside
            return
         end if
      end do
      status = loc_failed
      t = 0
      i = 0
   end subroutine locate

   !> Insert a vertex (kind, seg) at (px, py); status from `locate`. Points
   !> outside the block or on top of an existing vertex are not inserted.
   subroutine insert_point(tr, px, py, kind, seg, start, status)
      type(tri_t), intent(inout) :: tr
      real(wp), intent(in) :: px, py
      integer(ip), intent(in) :: kind, seg, start
      integer(ip), intent(out) :: status
      integer(ip) :: t, i, k
      real(wp) :: d
      call locate(tr, px, py, start, t, i, status)
      if (status == loc_outside .or. status == loc_failed) return
      do k = 1, 3
         d = hypot(tr%x(tr%v(k, t)) - px, tr%y(tr%v(k, t)) - py)
         if (d <= 1.0e-9_wp*tr%scale) then
            status = loc_failed
            return
         end if
      end do
      if (status == loc_inside) then
         call split_triangle(tr, t, px, py, kind, seg)
      else
         call split_edge(tr, t, i, px, py, kind, seg)
      end if
   end subroutine insert_point

   subroutine split_triangle(tr, t, px, py, kind, seg)
      type(tri_t), intent(inout) :: tr
      integer(ip), intent(in) :: t, kind, seg
      real(wp), intent(in) :: px, py
      integer(ip) :: p, a, b, c, na, nb, nc, t1, t2, ns
      integer(ip), allocatable :: stack(:)
      call add_vertex(tr, px, py, kind, seg, p)
      a = tr%v(1, t); b = tr%v(2, t); c = tr%v(3, t)
      na = tr%n(1, t); nb = tr%n(2, t); nc = tr%n(3, t)
      call new_triangle(tr, t1)
      call new_triangle(tr, t2)
      call set_tri(tr, t1, p, c, a, nb, t2, t)
      call set_tri(tr, t2, p, a, b, nc, t, t1)
      call set_tri(tr, t, p, b, c, na, t1, t2)
      call replace_nb(tr, nb, t, t1)
      call replace_nb(tr, nc, t, t2)
      allocate (stack(16))
      ns = 0
      call push(stack, ns, t); call push(stack, ns, t1); call push(stack, ns, t2)
      call legalize(tr, p, stack, ns)
   end subroutine split_triangle

   !> Split the edge opposite v(i,t) at (px, py).
   subroutine split_edge(tr, t, i, px, py, kind, seg)
      type(tri_t), intent(inout) :: tr
      integer(ip), intent(in) :: t, i, kind, seg
      real(wp), intent(in) :: px, py
      integer(ip) :: p, a, b, c, d, u, j, nb, nc, nbd, ndc, t1, u1, ns, kd, sg
      integer(ip), allocatable :: stack(:)
      a = tr%v(i, t); b = tr%v(nxt(i), t); c = tr%v(prv(i), t)
      nb = tr%n(nxt(i), t)     ! across c-a
      nc = tr%n(prv(i), t)     ! across a-b
      u = tr%n(i, t)
      kd = kind
      sg = seg
      if (u == 0 .and. kd == 0) then
         ! a point on the block boundary: it lies on the input edge of b-c
         kd = 2
         sg = edge_seg(tr, b, c)
      end if
      call add_vertex(tr, px, py, kd, sg, p)
      call new_triangle(tr, t1)
      if (u /= 0) then
         do j = 1, 3
            if (tr%v(j, u) /= b .and. tr%v(j, u) /= c) exit
         end do
         d = tr%v(j, u)
         nbd = tr%n(nxt(j), u)
         ndc = tr%n(prv(j), u)
         call new_triangle(tr, u1)
         call set_tri(tr, t, p, a, b, nc, u, t1)
         call set_tri(tr, t1, p, c, a, nb, t, u1)
         call set_tri(tr, u, p, b, d, nbd, u1, t)
         call set_tri(tr, u1, p, d, c, ndc, t1, u)
         call replace_nb(tr, nb, t, t1)
         call replace_nb(tr, ndc, u, u1)
      else
         call set_tri(tr, t, p, a, b, nc, 0_ip, t1)
         call set_tri(tr, t1, p, c, a, nb, t, 0_ip)
         call replace_nb(tr, nb, t, t1)
      end if
      allocate (stack(16))
      ns = 0
      call push(stack, ns, t); call push(stack, ns, t1)
      if (u /= 0) then
         call push(stack, ns, u); call push(stack, ns, u1)
      end if
      call legalize(tr, p, stack, ns)
   end subroutine split_edge

   !> Input edge a boundary piece b-c lies on.
   integer(ip) function edge_seg(tr, b, c) result(e)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: b, c
      integer(ip) :: n
      n = tr%ncorner
      if (tr%kind(b) == 2) then
         e = tr%seg(b)
      else if (tr%kind(c) == 2) then
         e = tr%seg(c)
      else
         ! two input corners, adjacent in the clockwise ring
         if (tr%seg(c) == merge(1_ip, tr%seg(b) + 1, tr%seg(b) == n)) then
            e = tr%seg(b)
         else
            e = tr%seg(c)
         end if
      end if
   end function edge_seg

   !> Lawson flips around a new vertex p (vertex 1 of the stacked triangles).
   subroutine legalize(tr, p, stack, ns)
      type(tri_t), intent(inout) :: tr
      integer(ip), intent(in) :: p
      integer(ip), allocatable, intent(inout) :: stack(:)
      integer(ip), intent(inout) :: ns
      integer(ip) :: t, u, guard
      guard = 0
      do while (ns > 0)
         t = stack(ns)
         ns = ns - 1
         if (tr%v(1, t) /= p) cycle
         guard = guard + 1
         if (guard > 10000) exit
         if (should_flip(tr, t, 1_ip)) then
            u = tr%n(1, t)
            call flip(tr, t, 1_ip)
            call push(stack, ns, t)
            call push(stack, ns, u)
         end if
      end do
      ns = 0
   end subroutine legalize

   ! ------------------------------------------------------- refinement

   !> Is vertex v on input edge e (corners lie on their two edges)?
   logical function on_input_edge(tr, v, e)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: v, e
      integer(ip) :: n
      n = tr%ncorner
      select case (tr%kind(v))
      case (1)
         on_input_edge = e == tr%seg(v) .or. e == merge(n, tr%seg(v) - 1, tr%seg(v) == 1)
      case (2)
         on_input_edge = e == tr%seg(v)
      case default
         on_input_edge = .false.
      end select
   end function on_input_edge

   !> Do u and w lie on the two edges of one sharp input corner?
   logical function across_sharp_corner(tr, u, w, equal_dist)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: u, w
      logical, intent(in) :: equal_dist
      integer(ip) :: k, e1, e2, n
      real(wp) :: du, dw
      across_sharp_corner = .false.
      if (tr%kind(u) == 0 .or. tr%kind(w) == 0) return
      n = tr%ncorner
      do k = 1, n
         if (.not. tr%sharp(k)) cycle
         e1 = merge(n, k - 1, k == 1)
         e2 = k
         if ((on_input_edge(tr, u, e1) .and. on_input_edge(tr, w, e2)) .or. &
             (on_input_edge(tr, u, e2) .and. on_input_edge(tr, w, e1))) then
            if (.not. equal_dist) then
               across_sharp_corner = .true.
               return
            end if
            ! concentric shells: only an edge between points at the same
            ! distance from the corner is left alone
            du = hypot(tr%x(u) - tr%x(k), tr%y(u) - tr%y(k))
            dw = hypot(tr%x(w) - tr%x(k), tr%y(w) - tr%y(k))
            if (abs(du - dw) <= 1.0e-3_wp*max(du, dw)) then
               across_sharp_corner = .true.
               return
            end if
         end if
      end do
   end function across_sharp_corner

   !> Ruppert refinement: split encroached boundary pieces, then insert the
   !> circumcentre of triangles with a small angle or an edge above edmax.
   subroutine refine(tr, edmax, maxv)
      type(tri_t), intent(inout) :: tr
      real(wp), intent(in) :: edmax
      integer(ip), intent(in) :: maxv
      integer(ip) :: head, t, i, a, b, c, st, u, k, j, ntri0
      integer(ip), allocatable :: queue(:)
      integer(ip) :: nq
      real(wp) :: s_target, cx, cy, q, lmax, lmin
      logical :: done
      s_target = sin(mesh_target_angle*pi/180.0_wp)
      allocate (queue(max(16_ip, 2*tr%nt)))
      nq = 0
      do t = 1, tr%nt
         call push(queue, nq, t)
      end do
      head = 0
      do while (head < nq)
         if (tr%nv >= maxv) exit
         head = head + 1
         t = queue(head)
         if (head > 1000000 .and. head > nq/2) then
            queue(1:nq - head) = queue(head + 1:nq)
            nq = nq - head
            head = 0
         end if
         ntri0 = tr%nt
         done = .false.
         ! encroached boundary pieces (apex inside the diametral circle)
         do i = 1, 3
            if (tr%n(i, t) /= 0) cycle
            a = tr%v(i, t); b = tr%v(nxt(i), t); c = tr%v(prv(i), t)
            if ((tr%x(b) - tr%x(a))*(tr%x(c) - tr%x(a)) + (tr%y(b) - tr%y(a))*(tr%y(c) - &
                tr%y(a)) >= 0.0_wp) cycle
            if (across_sharp_corner(tr, a, b, .false.) .or. across_sharp_corner(tr, a, c, .false.)) cycle
            if (edge_len(tr, t, i) < 1.0e-6_wp*tr%scale) cycle
            call split_point(tr, b, c, cx, cy)
            call split_edge(tr, t, i, cx, cy, 0_ip, 0_ip)
            done = .true.
            exit
         end do
         if (.not. done) then
            call quality(tr, t, q, lmax, lmin, i)
            if (q < s_target .or. lmax > edmax*(1.0_wp + 1.0e-6_wp)) then
               ! i: vertex opposite the shortest edge
               if (lmax <= edmax*(1.0_wp + 1.0e-6_wp) .and. &
                   across_sharp_corner(tr, tr%v(nxt(i), t), tr%v(prv(i), t), .true.)) then
                  cycle
               end if
               if (lmin < 1.0e-6_wp*tr%scale) cycle
               call circumcentre(tr, t, cx, cy)
               call locate(tr, cx, cy, t, u, k, st)
               if (st == loc_outside) then
                  ! beyond a boundary piece: split that piece instead
                  if (edge_len(tr, u, k) >= 1.0e-6_wp*tr%scale) then
                     b = tr%v(nxt(k), u); c = tr%v(prv(k), u)
                     call split_point(tr, b, c, cx, cy)
                     call split_edge(tr, u, k, cx, cy, 0_ip, 0_ip)
                     done = .true.
                  end if
               else if (st == loc_inside .or. st == loc_edge) then
                  call encroached_near(tr, u, cx, cy, j, k)
                  if (j > 0) then
                     b = tr%v(nxt(k), j); c = tr%v(prv(k), j)
                     call split_point(tr, b, c, cx, cy)
                     call split_edge(tr, j, k, cx, cy, 0_ip, 0_ip)
                     done = .true.
                  else
                     call insert_point(tr, cx, cy, 0_ip, 0_ip, u, st)
                     done = st == loc_inside .or. st == loc_edge
                  end if
               end if
            end if
         end if
         if (done) then
            ! the changed triangles: the new ones and those around the new point
            do k = ntri0 + 1, tr%nt
               call push(queue, nq, k)
            end do
            call push_star(tr, tr%nv, queue, nq)
            call push(queue, nq, t)
         end if
      end do
   end subroutine refine

   !> Where to split boundary piece b-c: the midpoint, or, next to a corner
   !> sharper than 60 degrees, the point whose distance from the corner is
   !> the power of two (times the block extent) nearest half the piece
   !> (concentric shells: both edges of the corner get points at the same
   !> distances, so the zones in the corner are isosceles).
   subroutine split_point(tr, b, c, px, py)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: b, c
      real(wp), intent(out) :: px, py
      integer(ip) :: o, f
      real(wp) :: l, d
      px = 0.5_wp*(tr%x(b) + tr%x(c))
      py = 0.5_wp*(tr%y(b) + tr%y(c))
      o = 0
      if (tr%kind(b) == 1) then
         if (tr%sharp(tr%seg(b))) then
            o = b; f = c
         end if
      end if
      if (o == 0 .and. tr%kind(c) == 1) then
         if (tr%sharp(tr%seg(c))) then
            o = c; f = b
         end if
      end if
      if (o == 0) return
      l = hypot(tr%x(f) - tr%x(o), tr%y(f) - tr%y(o))
      d = tr%scale*2.0_wp**nint(log(0.5_wp*l/tr%scale)/log(2.0_wp))
      if (d <= 0.2_wp*l .or. d >= 0.8_wp*l) return
      px = tr%x(o) + (tr%x(f) - tr%x(o))*d/l
      py = tr%y(o) + (tr%y(f) - tr%y(o))*d/l
   end subroutine split_point

   !> Boundary piece of u or its neighbours whose diametral circle holds (cx, cy).
   subroutine encroached_near(tr, u, cx, cy, j, k)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: u
      real(wp), intent(in) :: cx, cy
      integer(ip), intent(out) :: j, k
      integer(ip) :: cand(4), m, i, b, c
      cand(1) = u
      cand(2:4) = tr%n(:, u)
      do m = 1, 4
         j = cand(m)
         if (j == 0) cycle
         do i = 1, 3
            if (tr%n(i, j) /= 0) cycle
            b = tr%v(nxt(i), j); c = tr%v(prv(i), j)
            if ((tr%x(b) - cx)*(tr%x(c) - cx) + (tr%y(b) - cy)*(tr%y(c) - cy) < 0.0_wp) then
               k = i
               return
            end if
         end do
      end do
      j = 0
      k = 0
   end subroutine encroached_near

   !> Push every triangle around vertex v.
   subroutine push_star(tr, v, queue, nq)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: v
      integer(ip), allocatable, intent(inout) :: queue(:)
      integer(ip), intent(inout) :: nq
      integer(ip), allocatable :: star(:), ring(:)
      integer(ip) :: ns, k
      logical :: closed
      call vertex_star(tr, v, star, ring, ns, closed)
      do k = 1, ns
         call push(queue, nq, star(k))
      end do
   end subroutine push_star

   !> Triangles around v counter-clockwise and the ring of neighbours (the
   !> vertex after v in each triangle); `closed` false for boundary vertices.
   subroutine vertex_star(tr, v, star, ring, ns, closed)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: v
      integer(ip), allocatable, intent(out) :: star(:), ring(:)
      integer(ip), intent(out) :: ns
      logical, intent(out) :: closed
      integer(ip) :: t, k, t0, guard
      allocate (star(32), ring(32))
      ns = 0
      closed = .false.
      t0 = tr%vtri(v)
      if (t0 == 0) return
      ! rotate clockwise to the first triangle (or all the way round)
      t = t0
      do guard = 1, 1000
         k = vpos(t)
         if (tr%n(nxt(k), t) == 0) exit     ! edge v - v(prv k) ... see below
         t = tr%n(nxt(k), t)
         if (t == t0) then
            closed = .true.
            exit
         end if
      end do
      ! t: the clockwise-most triangle; walk counter-clockwise
      t0 = t
      do guard = 1, 1000
         k = vpos(t)
         if (ns >= size(ring)) call grow(ring)
         call push(star, ns, t)
         ring(ns) = tr%v(nxt(k), t)
         if (tr%n(prv(k), t) == 0) exit
         t = tr%n(prv(k), t)
         if (t == t0) exit
      end do
   contains
      integer(ip) function vpos(tt)
         integer(ip), intent(in) :: tt
         do vpos = 1, 3
            if (tr%v(vpos, tt) == v) return
         end do
      end function vpos
      subroutine grow(a)
         integer(ip), allocatable, intent(inout) :: a(:)
         integer(ip), allocatable :: tmp(:)
         allocate (tmp(2*size(a)))
         tmp(1:size(a)) = a
         call move_alloc(tmp, a)
      end subroutine grow
   end subroutine vertex_star

   !> sin of the smallest angle of triangle t, longest and shortest edge, and
   !> the vertex opposite the shortest edge.
   subroutine quality(tr, t, q, lmax, lmin, imin)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: t
      real(wp), intent(out) :: q, lmax, lmin
      integer(ip), intent(out) :: imin
      real(wp) :: l(3), a2
      integer(ip) :: i
      do i = 1, 3
         l(i) = edge_len(tr, t, i)
      end do
      associate (a => tr%v(1, t), b => tr%v(2, t), c => tr%v(3, t))
         a2 = orient(tr%x(a), tr%y(a), tr%x(b), tr%y(b), tr%x(c), tr%y(c))
      end associate
      imin = minloc(l, 1)
      lmax = maxval(l)
      lmin = minval(l)
      ! the smallest angle is opposite the shortest edge, between the other two
      q = a2/max((l(nxt(imin))*l(prv(imin))), tiny(1.0_wp))
   end subroutine quality

   subroutine circumcentre(tr, t, cx, cy)
      type(tri_t), intent(in) :: tr
      integer(ip), intent(in) :: t
      real(wp), intent(out) :: cx, cy
      real(wp) :: bx, by, qx, qy, d
      associate (a => tr%v(1, t), b => tr%v(2, t), c => tr%v(3, t))
         bx = tr%x(b) - tr%x(a); by = tr%y(b) - tr%y(a)
         qx = tr%x(c) - tr%x(a); qy = tr%y(c) - tr%y(a)
         d = 2.0_wp*(bx*qy - by*qx)
         cx = tr%x(a) + (qy*(bx*bx + by*by) - by*(qx*qx + qy*qy))/d
         cy = tr%y(a) + (bx*(qx*qx + qy*qy) - qx*(bx*bx + by*by))/d
      end associate
   end subroutine circumcentre

   !> Laplacian smoothing of interior vertices; a move is kept only when the
   !> smallest angle around the vertex does not drop.
   subroutine smooth(tr, passes, edmax)
      type(tri_t), intent(inout) :: tr
      integer, intent(in) :: passes
      real(wp), intent(in) :: edmax
      integer(ip), allocatable :: star(:), ring(:)
      integer(ip) :: v, ns, k, pass
      logical :: closed
      real(wp) :: x0, y0, xn, yn, q0, q1
      do pass = 1, passes
         do v = 1, tr%nv
            if (tr%kind(v) /= 0) cycle
            call vertex_star(tr, v, star, ring, ns, closed)
            if (.not. closed .or. ns < 3) cycle
            x0 = tr%x(v); y0 = tr%y(v)
            xn = 0.0_wp; yn = 0.0_wp
            do k = 1, ns
               xn = xn + tr%x(ring(k)); yn = yn + tr%y(ring(k))
            end do
            xn = xn/ns; yn = yn/ns
            q0 = star_quality(star, ns)
            tr%x(v) = xn; tr%y(v) = yn
            q1 = star_quality(star, ns)
            if (.not. q1 > q0 .or. star_edge(ring, ns) > edmax) then
               tr%x(v) = x0; tr%y(v) = y0
            end if
         end do
      end do
   contains
      real(wp) function star_edge(rg, m) result(l)
         integer(ip), intent(in) :: rg(:), m
         integer(ip) :: kk
         l = 0.0_wp
         do kk = 1, m
            l = max(l, hypot(tr%x(rg(kk)) - tr%x(v), tr%y(rg(kk)) - tr%y(v)))
         end do
      end function star_edge
      real(wp) function star_quality(st, m) result(qq)
         integer(ip), intent(in) :: st(:), m
         integer(ip) :: kk, im
         real(wp) :: q, lmax, lmin
         qq = huge(1.0_wp)
         do kk = 1, m
            call quality(tr, st(kk), q, lmax, lmin, im)
            qq = min(qq, q)
         end do
      end function star_quality
   end subroutine smooth

   !> Renumber: the boundary ring clockwise from input corner 1, then the
   !> interior points.
   subroutine export(tr, mesh)
      type(tri_t), intent(in) :: tr
      type(mesh_t), intent(out) :: mesh
      integer(ip), allocatable :: cw(:), newid(:)
      integer(ip) :: t, i, a, b, v, k, nb
      allocate (cw(tr%nv), newid(tr%nv))
      cw = 0
      do t = 1, tr%nt
         do i = 1, 3
            if (tr%n(i, t) /= 0) cycle
            a = tr%v(nxt(i), t); b = tr%v(prv(i), t)
            ! a -> b is counter-clockwise along the boundary
            cw(b) = a
         end do
      end do
      newid = 0
      nb = 0
      v = 1
      do
         nb = nb + 1
         newid(v) = nb
         v = cw(v)
         if (v == 1 .or. v == 0 .or. nb > tr%nv) exit
      end do
      mesh%nb = nb
      mesh%np = tr%nv
      allocate (mesh%x(tr%nv), mesh%y(tr%nv), mesh%orig(nb))
      k = nb
      do v = 1, tr%nv
         if (newid(v) == 0) then
            k = k + 1
            newid(v) = k
         end if
         mesh%x(newid(v)) = tr%x(v)
         mesh%y(newid(v)) = tr%y(v)
         if (newid(v) <= nb) mesh%orig(newid(v)) = merge(tr%seg(v), 0_ip, tr%kind(v) == 1)
      end do
      mesh%nt = tr%nt
      allocate (mesh%tri(3, tr%nt))
      do t = 1, tr%nt
         mesh%tri(:, t) = newid(tr%v(:, t))
      end do
   end subroutine export

   ! ------------------------------------------------------------------ QUAD

   !> QUAD xw yw: a convex quadrilateral (clockwise) cut into a grid of cells,
   !> each cell into 4 triangles around a centre gridpoint.
   subroutine mesh_quad(x, y, xw, yw, mesh, error)
      real(wp), intent(in) :: x(:), y(:), xw, yw
      type(mesh_t), intent(out) :: mesh
      type(error_t), allocatable, intent(out) :: error
      integer(ip) :: na, nbb, i, j, k, c, nb, np
      integer(ip), allocatable :: id(:, :), cid(:, :)
      real(wp) :: l(4), s, t, sc
      if (size(x) /= 4) then
         call set_error(error, 'QUAD needs a quadrilateral block (4 corners)')
         return
      end if
      sc = max(maxval(x) - minval(x), maxval(y) - minval(y))
      do k = 1, 4
         i = merge(4_ip, k - 1, k == 1); j = merge(1_ip, k + 1, k == 4)
         if (orient(x(i), y(i), x(k), y(k), x(j), y(j)) >= -1.0e-9_wp*sc**2) then
            call set_error(error, 'QUAD needs a convex quadrilateral block')
            return
         end if
      end do
      do k = 1, 4
         j = merge(1_ip, k + 1, k == 4)
         l(k) = hypot(x(j) - x(k), y(j) - y(k))
      end do
      ! edges 1 and 3 (s direction) are the x pair when edge 1 runs more along x
      if (abs(x(2) - x(1)) >= abs(y(2) - y(1))) then
         na = max(1_ip, ceiling(max(l(1), l(3))/xw - 1.0e-9_wp, ip))
         nbb = max(1_ip, ceiling(max(l(2), l(4))/yw - 1.0e-9_wp, ip))
      else
         na = max(1_ip, ceiling(max(l(1), l(3))/yw - 1.0e-9_wp, ip))
         nbb = max(1_ip, ceiling(max(l(2), l(4))/xw - 1.0e-9_wp, ip))
      end if
      allocate (id(0:na, 0:nbb), cid(na, nbb))
      nb = 2*(na + nbb)
      np = (na + 1)*(nbb + 1) + na*nbb
      allocate (mesh%x(np), mesh%y(np), mesh%orig(nb), mesh%tri(3, 4*na*nbb))
      mesh%nb = nb
      mesh%np = np
      ! clockwise ring: edge 1 (t = 0), edge 2 (s = 1), edge 3 (t = 1), edge 4 (s = 0)
      k = 0
      do i = 0, na - 1
         k = k + 1; id(i, 0) = k
      end do
      do j = 0, nbb - 1
         k = k + 1; id(na, j) = k
      end do
      do i = na, 1, -1
         k = k + 1; id(i, nbb) = k
      end do
      do j = nbb, 1, -1
         k = k + 1; id(0, j) = k
      end do
      do j = 1, nbb - 1
         do i = 1, na - 1
            k = k + 1; id(i, j) = k
         end do
      end do
      do j = 1, nbb
         do i = 1, na
            k = k + 1; cid(i, j) = k
         end do
      end do
      mesh%orig = 0
      mesh%orig(id(0, 0)) = 1; mesh%orig(id(na, 0)) = 2
      mesh%orig(id(na, nbb)) = 3; mesh%orig(id(0, nbb)) = 4
      do j = 0, nbb
         do i = 0, na
            s = real(i, wp)/na; t = real(j, wp)/nbb
            call bilinear(s, t, mesh%x(id(i, j)), mesh%y(id(i, j)))
         end do
      end do
      do j = 1, nbb
         do i = 1, na
            k = cid(i, j)
            mesh%x(k) = 0.25_wp*(mesh%x(id(i - 1, j - 1)) + mesh%x(id(i, j - 1)) + &
                                 mesh%x(id(i, j)) + mesh%x(id(i - 1, j)))
            mesh%y(k) = 0.25_wp*(mesh%y(id(i - 1, j - 1)) + mesh%y(id(i, j - 1)) + &
                                 mesh%y(id(i, j)) + mesh%y(id(i - 1, j)))
         end do
      end do
      mesh%nt = 0
      do j = 1, nbb
         do i = 1, na
            c = cid(i, j)
            call add_tri(id(i - 1, j - 1), id(i, j - 1), c)
            call add_tri(id(i, j - 1), id(i, j), c)
            call add_tri(id(i, j), id(i - 1, j), c)
            call add_tri(id(i - 1, j), id(i - 1, j - 1), c)
         end do
      end do
   contains
      subroutine bilinear(s_, t_, px, py)
         real(wp), intent(in) :: s_, t_
         real(wp), intent(out) :: px, py
         px = (1 - s_)*(1 - t_)*x(1) + s_*(1 - t_)*x(2) + s_*t_*x(3) + (1 - s_)*t_*x(4)
         py = (1 - s_)*(1 - t_)*y(1) + s_*(1 - t_)*y(2) + s_*t_*y(3) + (1 - s_)*t_*y(4)
      end subroutine bilinear
      subroutine add_tri(a, b, cc)
         integer(ip), intent(in) :: a, b, cc
         mesh%nt = mesh%nt + 1
         if (orient(mesh%x(a), mesh%y(a), mesh%x(b), mesh%y(b), mesh%x(cc), mesh%y(cc)) > 0) then
            mesh%tri(:, mesh%nt) = [a, b, cc]
         else
            mesh%tri(:, mesh%nt) = [b, a, cc]
         end if
      end subroutine add_tri
   end subroutine mesh_quad

   ! ---------------------------------------------------------------- MANUAL

   !> MANUAL: gridpoints gx, gy in the order given, zones as triples of
   !> gridpoint numbers counted from the LAST gridpoint given (last = 1).
   !> A gridpoint within `snap` of a corner goes onto it; within `snap` of an
   !> edge it becomes a new corner on the edge (projected onto it).
   subroutine mesh_manual(x, y, gx, gy, zl, snap, mesh, error)
      real(wp), intent(in) :: x(:), y(:), gx(:), gy(:), snap
      integer, intent(in) :: zl(:)
      type(mesh_t), intent(out) :: mesh
      type(error_t), allocatable, intent(out) :: error
      integer(ip) :: n, ng, nz, k, c, e, j, nb, m, i, a, b, q, nbedge
      integer(ip), allocatable :: where_c(:), where_e(:), order(:), newid(:), cwnext(:)
      integer(ip), allocatable :: keys(:, :), used(:)
      real(wp), allocatable :: tpar(:), px(:), py(:)
      real(wp) :: d, t, dbest, tb, sc, area, asum, ar
      character(len=160) :: text
      n = size(x)
      ng = size(gx)
      nz = size(zl)/3
      sc = max(maxval(x) - minval(x), maxval(y) - minval(y))
      if (ng < 3 .or. nz < 1 .or. mod(size(zl), 3) /= 0) then
         call set_error(error, 'MANUAL needs at least 3 gridpoints and 1 zone (triples)')
         return
      end if
      allocate (where_c(ng), where_e(ng), tpar(ng), px(ng), py(ng))
      px = gx; py = gy
      where_c = 0; where_e = 0; tpar = 0
      do k = 1, ng
         dbest = huge(1.0_wp)
         do c = 1, n
            d = hypot(gx(k) - x(c), gy(k) - y(c))
            if (d < dbest) then
               dbest = d; where_c(k) = c
            end if
         end do
         if (dbest <= snap) then
            px(k) = x(where_c(k)); py(k) = y(where_c(k))
            cycle
         end if
         where_c(k) = 0
         dbest = huge(1.0_wp)
         do e = 1, n
            j = merge(1_ip, e + 1, e == n)
            call segment_distance(gx(k), gy(k), x(e), y(e), x(j), y(j), d, t)
            if (d < dbest) then
               dbest = d; where_e(k) = e; tb = t
            end if
         end do
         if (dbest <= snap) then
            e = where_e(k); j = merge(1_ip, e + 1, e == n)
            tpar(k) = tb
            px(k) = x(e) + tb*(x(j) - x(e)); py(k) = y(e) + tb*(y(j) - y(e))
            cycle
         end if
         where_e(k) = 0
         if (.not. point_in_polygon(x, y, gx(k), gy(k))) then
            write (text, '(a,i0,5a)') 'MANUAL gridpoint ', ng + 1 - k, ' (', &
               format_real(gx(k)), ', ', format_real(gy(k)), ') lies outside the block'
            call set_error(error, trim(text))
            return
         end if
      end do
      ! duplicates
      do k = 1, ng
         do j = k + 1, ng
            if (hypot(px(k) - px(j), py(k) - py(j)) <= 1.0e-9_wp*sc) then
               write (text, '(a,i0,a,i0,a)') 'MANUAL gridpoints ', ng + 1 - k, ' and ', &
                  ng + 1 - j, ' are at the same place'
               call set_error(error, trim(text))
               return
            end if
         end do
      end do
      do c = 1, n
         if (.not. any(where_c == c)) then
            write (text, '(5a)') 'MANUAL: block corner (', format_real(x(c)), ', ', &
               format_real(y(c)), ') has no gridpoint'
            call set_error(error, trim(text))
            return
         end if
      end do
      ! new clockwise ring: each corner, then the points on its edge by parameter
      allocate (order(ng), newid(ng))
      nb = 0
      newid = 0
      do c = 1, n
         k = findloc(where_c, c, 1)
         nb = nb + 1; order(nb) = k
         m = nb
         do k = 1, ng
            if (where_e(k) == c) then
               nb = nb + 1; order(nb) = k
            end if
         end do
         ! insertion sort of the edge points by parameter
         do i = m + 2, nb
            q = order(i)
            j = i - 1
            do while (j > m)
               if (tpar(order(j)) <= tpar(q)) exit
               order(j + 1) = order(j)
               j = j - 1
            end do
            order(j + 1) = q
         end do
      end do
      do i = 1, nb
         newid(order(i)) = i
      end do
      m = nb
      do k = 1, ng
         if (newid(k) == 0) then
            m = m + 1
            newid(k) = m
         end if
      end do
      mesh%nb = nb
      mesh%np = ng
      allocate (mesh%x(ng), mesh%y(ng), mesh%orig(nb), mesh%tri(3, nz))
      do k = 1, ng
         mesh%x(newid(k)) = px(k); mesh%y(newid(k)) = py(k)
      end do
      do i = 1, nb
         mesh%orig(i) = where_c(order(i))
      end do
      ! zones
      allocate (used(ng))
      used = 0
      asum = 0.0_wp
      mesh%nt = nz
      do i = 1, nz
         do j = 1, 3
            q = zl(3*(i - 1) + j)
            if (q < 1 .or. q > ng) then
               write (text, '(a,i0,a,i0,a,i0)') 'MANUAL zone ', i, ': gridpoint ', q, &
                  ' does not exist; gridpoints are 1 to ', ng
               call set_error(error, trim(text))
               return
            end if
            ! gridpoint q counts from the last given
            mesh%tri(j, i) = newid(ng + 1 - q)
            used(ng + 1 - q) = 1
         end do
         associate (v => mesh%tri(:, i))
            ar = 0.5_wp*orient(mesh%x(v(1)), mesh%y(v(1)), mesh%x(v(2)), mesh%y(v(2)), &
                               mesh%x(v(3)), mesh%y(v(3)))
         end associate
         if (abs(ar) <= 1.0e-9_wp*sc**2) then
            write (text, '(a,i0,a)') 'MANUAL zone ', i, ' is degenerate (no area)'
            call set_error(error, trim(text))
            return
         end if
         if (ar < 0.0_wp) mesh%tri(2:3, i) = mesh%tri([3, 2], i)
         asum = asum + abs(ar)
      end do
      if (any(used == 0)) then
         k = findloc(used, 0, 1)
         write (text, '(a,i0,a)') 'MANUAL gridpoint ', ng + 1 - k, ' belongs to no zone'
         call set_error(error, trim(text))
         return
      end if
      area = -polygon_signed_area(x, y)
      if (abs(asum - area) > 1.0e-9_wp*area) then
         write (text, '(4a)') 'MANUAL zones do not fill the block: zone area ', &
            trim(adjustl(fmt_real(asum, 15, 7))), ', block area ', &
            trim(adjustl(fmt_real(area, 15, 7)))
         call set_error(error, trim(text))
         return
      end if
      ! conformity: every directed zone edge is matched by its reverse, or lies
      ! on the ring (counter-clockwise, i.e. against the clockwise ring)
      allocate (cwnext(nb))
      do i = 1, nb
         cwnext(i) = merge(1_ip, i + 1, i == nb)
      end do
      allocate (keys(2, 3*nz))
      do i = 1, nz
         do j = 1, 3
            keys(1, 3*(i - 1) + j) = mesh%tri(j, i)
            keys(2, 3*(i - 1) + j) = mesh%tri(nxt(int(j, ip)), i)
         end do
      end do
      call sort_pairs(keys)
      nbedge = 0
      do i = 1, 3*nz
         a = keys(1, i); b = keys(2, i)
         if (i > 1) then
            if (keys(1, i - 1) == a .and. keys(2, i - 1) == b) then
               call set_error(error, 'MANUAL zones overlap (an edge is used twice the same way)')
               return
            end if
         end if
         if (a <= nb .and. b <= nb) then
            if (cwnext(b) == a) then
               nbedge = nbedge + 1
               cycle
            end if
         end if
         if (.not. has_pair(b, a)) then
            call set_error(error, 'MANUAL zones do not fit together (a zone edge has no ' &
                           //'neighbour and is not on the block boundary)')
            return
         end if
      end do
      if (nbedge /= nb) then
         call set_error(error, 'MANUAL zones do not cover the whole block boundary')
         return
      end if
   contains
      logical function has_pair(p, r)
         integer(ip), intent(in) :: p, r
         integer(ip) :: lo, hi, mid
         lo = 1; hi = size(keys, 2)
         has_pair = .false.
         do while (lo <= hi)
            mid = (lo + hi)/2
            if (keys(1, mid) == p .and. keys(2, mid) == r) then
               has_pair = .true.
               return
            end if
            if (keys(1, mid) < p .or. (keys(1, mid) == p .and. keys(2, mid) < r)) then
               lo = mid + 1
            else
               hi = mid - 1
            end if
         end do
      end function has_pair
   end subroutine mesh_manual

   !> Heap sort of integer pairs, lexicographic.
   subroutine sort_pairs(k)
      integer(ip), intent(inout) :: k(:, :)
      integer(ip) :: n, i, last
      n = size(k, 2)
      do i = n/2, 1, -1
         call sift(i, n)
      end do
      do last = n, 2, -1
         call swap(1_ip, last)
         call sift(1_ip, last - 1)
      end do
   contains
      logical function less(a, b)
         integer(ip), intent(in) :: a, b
         less = k(1, a) < k(1, b) .or. (k(1, a) == k(1, b) .and. k(2, a) < k(2, b))
      end function less
      subroutine swap(a, b)
         integer(ip), intent(in) :: a, b
         integer(ip) :: t(2)
         t = k(:, a); k(:, a) = k(:, b); k(:, b) = t
      end subroutine swap
      subroutine sift(start, n_)
         integer(ip), intent(in) :: start, n_
         integer(ip) :: root, child
         root = start
         do while (2*root <= n_)
            child = 2*root
            if (child < n_) then
               if (less(child, child + 1)) child = child + 1
            end if
            if (less(root, child)) then
               call swap(root, child)
               root = child
            else
               return
            end if
         end do
      end subroutine sift
   end subroutine sort_pairs

   ! --------------------------------------------------------------- queries

   !> Smallest zone angle of a mesh (degrees).
   pure real(wp) function mesh_min_angle(mesh) result(amin)
      type(mesh_t), intent(in) :: mesh
      integer(ip) :: t, i, a, b, c
      real(wp) :: ux, uy, vx, vy
      amin = 180.0_wp
      do t = 1, mesh%nt
         do i = 1, 3
            a = mesh%tri(i, t)
            b = mesh%tri(merge(1, i + 1, i == 3), t)
            c = mesh%tri(merge(3, i - 1, i == 1), t)
            ux = mesh%x(b) - mesh%x(a); uy = mesh%y(b) - mesh%y(a)
            vx = mesh%x(c) - mesh%x(a); vy = mesh%y(c) - mesh%y(a)
            amin = min(amin, abs(atan2(ux*vy - uy*vx, ux*vx + uy*vy))*180.0_wp/pi)
         end do
      end do
   end function mesh_min_angle

   !> Sum of the signed zone areas (counter-clockwise positive).
   pure real(wp) function mesh_area(mesh) result(a)
      type(mesh_t), intent(in) :: mesh
      integer(ip) :: t
      a = 0.0_wp
      do t = 1, mesh%nt
         associate (v => mesh%tri(:, t))
            a = a + 0.5_wp*orient(mesh%x(v(1)), mesh%y(v(1)), mesh%x(v(2)), mesh%y(v(2)), &
                                  mesh%x(v(3)), mesh%y(v(3)))
         end associate
      end do
   end function mesh_area

end module zones_mesh
