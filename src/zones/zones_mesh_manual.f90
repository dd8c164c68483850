!> GENERATE MANUAL (manual Section 4.5): zones given gridpoint by gridpoint,
!> snapped onto the block's corners and edges and checked for conformity.
module zones_mesh_manual
   use core_sort, only: sort_order
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use core_output, only: format_real, fmt_real
   use core_sort, only: sort_order_pairs
   use geometry_polygon, only: point_in_polygon, polygon_signed_area, segment_distance
   use zones_mesh_base, only: mesh_t, nxt, orient
   implicit none
   private
   public :: mesh_manual

contains

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
      integer(ip), allocatable :: where_c(:), where_e(:), order(:), newid(:), cwnext(:), perm(:)
      integer(ip), allocatable :: keys(:, :), used(:), kperm(:)
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
      allocate (order(ng), newid(ng), perm(ng))
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
         ! the edge points in order of their parameter along the edge
         call sort_order(tpar(order(m + 1:nb)), perm(1:nb - m))
         order(m + 1:nb) = order(m + perm(1:nb - m))
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
      allocate (kperm(3*nz))
      call sort_order_pairs(keys(1, :), keys(2, :), kperm)
      keys = keys(:, kperm)
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

end module zones_mesh_manual
