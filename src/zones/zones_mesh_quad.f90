!> GENERATE QUAD (manual Section 4.5): a convex quadrilateral block cut into
!> a grid of cells, each cell into four triangles around a centre gridpoint.
module zones_mesh_quad
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use zones_mesh_base, only: mesh_t, orient
   implicit none
   private
   public :: mesh_quad

contains

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

end module zones_mesh_quad
