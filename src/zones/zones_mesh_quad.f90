!> GENERATE QUAD (manual Section 4.5): a convex quadrilateral block cut into
!> a grid of cells, each cell into four triangles around a centre gridpoint.
!> Corners lying on a straight edge (a 180 degree vertex, left where a joint
!> ends on the block's edge or given so in BLOCK) are kept as gridpoints of
!> that edge: the four other corners make the quadrilateral.
module zones_mesh_quad
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use zones_mesh_base, only: mesh_t, orient
   implicit none
   private
   public :: mesh_quad

contains

   !> QUAD xw yw: a convex quadrilateral (clockwise) cut into a grid of cells,
   !> each cell into 4 triangles around a centre gridpoint. The block may have
   !> more than four corners when the others lie on its edges (straight
   !> angles): each such corner becomes a gridpoint of its edge, the edge's
   !> cells shared among its pieces by length, and the inner gridpoints placed
   !> by transfinite (Coons) interpolation of the four edges (the bilinear map
   !> when every edge is evenly divided).
   subroutine mesh_quad(x, y, xw, yw, mesh, error)
      real(wp), intent(in) :: x(:), y(:), xw, yw
      type(mesh_t), intent(out) :: mesh
      type(error_t), allocatable, intent(out) :: error
      integer(ip) :: na, nbb, i, j, k, c, nb, np, n, m, q(4), nside(4), ncell(4), shift
      integer(ip), allocatable :: id(:, :), cid(:, :), ring(:), newid(:)
      integer(ip), allocatable :: eo(:, :)
      real(wp), allocatable :: ex(:, :), ey(:, :), xs(:), ys(:)
      real(wp) :: l(4), s, t, sc, cx(4), cy(4), sgn
      logical, allocatable :: straight(:)
      n = size(x)
      sc = max(maxval(x) - minval(x), maxval(y) - minval(y))
      allocate (straight(n))
      do k = 1, n
         i = merge(n, k - 1, k == 1); j = merge(1_ip, k + 1, k == n)
         straight(k) = abs(orient(x(i), y(i), x(k), y(k), x(j), y(j))) <= 1.0e-9_wp*sc**2 .and. &
                       (x(k) - x(i))*(x(j) - x(k)) + (y(k) - y(i))*(y(j) - y(k)) > 0.0_wp
      end do
      if (count(.not. straight) /= 4) then
         call set_error(error, 'QUAD needs a quadrilateral block (4 corners, others only on ' &
                        //'its straight edges)')
         return
      end if
      m = 0
      do k = 1, n
         if (straight(k)) cycle
         m = m + 1
         q(m) = k
      end do
      cx = x(q); cy = y(q)
      do k = 1, 4
         i = merge(4_ip, k - 1, k == 1); j = merge(1_ip, k + 1, k == 4)
         if (orient(cx(i), cy(i), cx(k), cy(k), cx(j), cy(j)) >= -1.0e-9_wp*sc**2) then
            call set_error(error, 'QUAD needs a convex quadrilateral block')
            return
         end if
      end do
      do k = 1, 4
         j = merge(1_ip, k + 1, k == 4)
         l(k) = hypot(cx(j) - cx(k), cy(j) - cy(k))
         nside(k) = modulo(q(j) - q(k) - 1, n) + 1         ! pieces of side k
      end do
      ! edges 1 and 3 (s direction) are the x pair when edge 1 runs more along x
      if (abs(cx(2) - cx(1)) >= abs(cy(2) - cy(1))) then
         na = max(1_ip, ceiling(max(l(1), l(3))/xw - 1.0e-9_wp, ip))
         nbb = max(1_ip, ceiling(max(l(2), l(4))/yw - 1.0e-9_wp, ip))
      else
         na = max(1_ip, ceiling(max(l(1), l(3))/yw - 1.0e-9_wp, ip))
         nbb = max(1_ip, ceiling(max(l(2), l(4))/xw - 1.0e-9_wp, ip))
      end if
      na = max(na, nside(1), nside(3))
      nbb = max(nbb, nside(2), nside(4))
      ncell = [na, nbb, na, nbb]
      ! the gridpoints of each side, from its first corner to the next
      allocate (ex(0:max(na, nbb), 4), ey(0:max(na, nbb), 4), eo(0:max(na, nbb), 4))
      do k = 1, 4
         call divide_side(q(k), nside(k), ncell(k), ex(:, k), ey(:, k), eo(:, k))
      end do
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
      do i = 0, na - 1
         mesh%orig(id(i, 0)) = eo(i, 1)
         mesh%orig(id(na - i, nbb)) = eo(i, 3)
      end do
      do j = 0, nbb - 1
         mesh%orig(id(na, j)) = eo(j, 2)
         mesh%orig(id(0, nbb - j)) = eo(j, 4)
      end do
      do j = 0, nbb
         do i = 0, na
            s = real(i, wp)/na; t = real(j, wp)/nbb
            if (all(nside == 1)) then
               call bilinear(s, t, mesh%x(id(i, j)), mesh%y(id(i, j)))
            else
               call coons(i, j, s, t, mesh%x(id(i, j)), mesh%y(id(i, j)))
            end if
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
      sgn = 0.0_wp
      do j = 1, nbb
         do i = 1, na
            c = cid(i, j)
            call add_tri(id(i - 1, j - 1), id(i, j - 1), c)
            call add_tri(id(i, j - 1), id(i, j), c)
            call add_tri(id(i, j), id(i - 1, j), c)
            call add_tri(id(i - 1, j), id(i - 1, j - 1), c)
         end do
      end do
      if (allocated(error)) return
      ! ring point 1 is the block's corner 1 (zones_apply_mesh keeps the
      ! corners in place when the ring gains no point)
      shift = findloc(mesh%orig, 1_ip, dim=1) - 1
      if (shift > 0) then
         allocate (newid(np))
         newid = [(merge(modulo(k - 1 - shift, nb) + 1, k, k <= nb), k=1, np)]
         allocate (xs(np), ys(np), ring(nb))
         xs(newid) = mesh%x; ys(newid) = mesh%y; ring(newid(1:nb)) = mesh%orig
         mesh%x = xs; mesh%y = ys; mesh%orig = ring
         do k = 1, mesh%nt
            mesh%tri(:, k) = newid(mesh%tri(:, k))
         end do
      end if
   contains
      !> Side k0 -> next corner that is not straight (npc pieces) cut into nc
      !> cells: one at least per piece, the rest each to the piece whose cells
      !> are then longest; po: the input corner a gridpoint stands on, or 0.
      subroutine divide_side(k0, npc, nc, px, py, po)
         integer(ip), intent(in) :: k0, npc, nc
         real(wp), intent(out) :: px(0:), py(0:)
         integer(ip), intent(out) :: po(0:)
         integer(ip) :: p, a, b, cnt(npc), ii, kk
         real(wp) :: lp(npc), f
         do p = 1, npc
            a = modulo(k0 + p - 2, n) + 1; b = modulo(k0 + p - 1, n) + 1
            lp(p) = hypot(x(b) - x(a), y(b) - y(a))
         end do
         cnt = 1
         do ii = npc + 1, nc
            p = maxloc(lp/cnt, dim=1)
            cnt(p) = cnt(p) + 1
         end do
         po = 0
         kk = 0
         do p = 1, npc
            a = modulo(k0 + p - 2, n) + 1; b = modulo(k0 + p - 1, n) + 1
            po(kk) = a
            do ii = 0, cnt(p)
               f = real(ii, wp)/cnt(p)
               px(kk + ii) = (1 - f)*x(a) + f*x(b)
               py(kk + ii) = (1 - f)*y(a) + f*y(b)
            end do
            kk = kk + cnt(p)
         end do
         po(kk) = modulo(k0 + npc - 1, n) + 1
      end subroutine divide_side
      subroutine bilinear(s_, t_, px, py)
         real(wp), intent(in) :: s_, t_
         real(wp), intent(out) :: px, py
         px = (1 - s_)*(1 - t_)*cx(1) + s_*(1 - t_)*cx(2) + s_*t_*cx(3) + (1 - s_)*t_*cx(4)
         py = (1 - s_)*(1 - t_)*cy(1) + s_*(1 - t_)*cy(2) + s_*t_*cy(3) + (1 - s_)*t_*cy(4)
      end subroutine bilinear
      !> Transfinite interpolation of the four sides' gridpoints
      subroutine coons(i_, j_, s_, t_, px, py)
         integer(ip), intent(in) :: i_, j_
         real(wp), intent(in) :: s_, t_
         real(wp), intent(out) :: px, py
         real(wp) :: bx, by
         call bilinear(s_, t_, bx, by)
         px = (1 - t_)*ex(i_, 1) + t_*ex(na - i_, 3) + s_*ex(j_, 2) + (1 - s_)*ex(nbb - j_, 4) - bx
         py = (1 - t_)*ey(i_, 1) + t_*ey(na - i_, 3) + s_*ey(j_, 2) + (1 - s_)*ey(nbb - j_, 4) - by
      end subroutine coons
      !> One zone, counter-clockwise; every zone of the grid turns the same
      !> way round its cell, so one turning the other way (a grid folded by
      !> corners crowded on one side) is refused rather than overlapped.
      subroutine add_tri(a, b, cc)
         integer(ip), intent(in) :: a, b, cc
         real(wp) :: o
         if (allocated(error)) return
         mesh%nt = mesh%nt + 1
         o = orient(mesh%x(a), mesh%y(a), mesh%x(b), mesh%y(b), mesh%x(cc), mesh%y(cc))
         if (sgn == 0.0_wp) sgn = sign(1.0_wp, o)
         if (o*sgn <= 0.0_wp) then
            call set_error(error, 'QUAD: the corners on this block''s edges fold its grid ' &
                           //'(a zone turned inside out); use AUTO or EDGE for it')
            return
         end if
         if (o > 0) then
            mesh%tri(:, mesh%nt) = [a, b, cc]
         else
            mesh%tri(:, mesh%nt) = [b, a, cc]
         end if
      end subroutine add_tri
   end subroutine mesh_quad

end module zones_mesh_quad
