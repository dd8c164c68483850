!> Boundary-element far field (src/be/be_kelvin.f90).
!> References:
!>  1. the line-load field obeys plane-strain Hooke's law: the stresses of
!>     line_load_field equal (lambda + 2G) e_xx + lambda e_yy etc. of the
!>     strains of its displacements (central differences, h = 1e-5 a;
!>     tolerance 1e-5 relative to the largest stress component);
!>  2. far from the element the displacement tends to the 2-D Kelvin point
!>     force 2 a P (differences of u between two far points, 0.1 %);
!>  3. a circular cavity of radius R in an infinite plane expanded by u_r
!>     needs the pressure p = 2 G u_r / R (Lame): the stiffness of 256
!>     straight elements on the circle gives the corner forces -p n L
!>     (tolerance 1 %; the error is first order in the element size on a
!>     curved wall: -2.3 %, -1.1 % at 64, 128 elements), with and without
!>     BE FIX points; a rigid rotation of a cavity wall in an infinite plane
!>     is resisted by the torque M = 4 pi G R^2 theta (u_theta = theta R^2 / r),
!>     checked to 2 %;
!>  4. a rectangle (verification C's 30 x 12 m outer boundary, elements of
!>     1.5 and 0.5 m, with and without BE FIX) displaced as the exact
!>     infinite-plane field of two opposite line loads inside it (a shear
!>     pair over the crack of verification C): the work u . K u equals the
!>     work of the exact tractions (4-point Gauss along each element, linear
!>     shape functions) within 1 % (measured 0.8 % at 1.5 m, 0.1 % at 0.5 m)
!>     and the error does not grow with refinement. Without BE FIX the
!>     corner forces of a random displacement sum to zero (1e-9 of the sum
!>     of their sizes): nothing else holds the model's translation.
program test_be
   use core_kinds, only: wp
   use core_error, only: error_t
   use be_kelvin, only: line_load_field, be_stiffness
   use testing, only: check, check_close, testing_finish, testing_fixed_seed
   implicit none
   real(wp), parameter :: pi = 3.14159265358979323846_wp
   real(wp), parameter :: g = 1.0e9_wp, nu = 0.25_wp

   call testing_fixed_seed()
   call hooke_check(0.7_wp, 0.4_wp)
   call hooke_check(-1.3_wp, -0.2_wp)
   call hooke_check(2.5_wp, 1.5_wp)
   call kelvin_far()
   call cavity(.false.)
   call cavity(.true.)
   call rectangle(.true.)
   call rectangle(.false.)
   call testing_finish()

contains

   subroutine hooke_check(x, y)
      real(wp), intent(in) :: x, y
      real(wp), parameter :: a = 0.5_wp
      real(wp) :: h, u(2, 2), s(3, 2), upx(2, 2), umx(2, 2), upy(2, 2), umy(2, 2), sd(3, 2)
      real(wp) :: exx, eyy, exy, lam, smax
      integer :: k
      character(len=80) :: label
      h = 1.0e-5_wp*a
      call line_load_field(x, y, a, g, nu, u, s)
      call line_load_field(x + h, y, a, g, nu, upx, sd)
      call line_load_field(x - h, y, a, g, nu, umx, sd)
      call line_load_field(x, y + h, a, g, nu, upy, sd)
      call line_load_field(x, y - h, a, g, nu, umy, sd)
      lam = 2.0_wp*g*nu/(1.0_wp - 2.0_wp*nu)
      do k = 1, 2
         exx = (upx(1, k) - umx(1, k))/(2.0_wp*h)
         eyy = (upy(2, k) - umy(2, k))/(2.0_wp*h)
         exy = 0.5_wp*((upy(1, k) - umy(1, k))/(2.0_wp*h) + (upx(2, k) - umx(2, k))/(2.0_wp*h))
         smax = maxval(abs(s(:, k)))
         write (label, '(a,2f6.2,a,i0)') 'Hooke at', x, y, ' load ', k
         call check_close(((lam + 2.0_wp*g)*exx + lam*eyy)/smax, s(1, k)/smax, 1.0e-5_wp, &
                          trim(label)//' sxx')
         call check_close((lam*exx + (lam + 2.0_wp*g)*eyy)/smax, s(2, k)/smax, 1.0e-5_wp, &
                          trim(label)//' syy')
         call check_close(2.0_wp*g*exy/smax, s(3, k)/smax, 1.0e-5_wp, trim(label)//' sxy')
      end do
   end subroutine hooke_check

   !> u_y(r2) - u_y(r1) of a point force F = 2 a Py on the y axis:
   !> F / (8 pi G (1 - nu)) (-(3 - 4 nu) ln(r2 / r1)) (Kelvin, plane strain).
   subroutine kelvin_far()
      real(wp), parameter :: a = 0.5_wp
      real(wp) :: u1(2, 2), u2(2, 2), s(3, 2), expected
      call line_load_field(0.0_wp, 200.0_wp, a, g, nu, u1, s)
      call line_load_field(0.0_wp, 400.0_wp, a, g, nu, u2, s)
      expected = 2.0_wp*a/(8.0_wp*pi*g*(1.0_wp - nu))*(-(3.0_wp - 4.0_wp*nu)*log(2.0_wp))
      call check_close((u2(2, 2) - u1(2, 2))/abs(expected), expected/abs(expected), 1.0e-3_wp, &
                       'Kelvin far field, Py')
      ! Fx: u_x = F / (8 pi G (1 - nu)) (-(3 - 4 nu) ln r + x^2 / r^2), x = 0 here
      call check_close((u2(1, 1) - u1(1, 1))/abs(expected), expected/abs(expected), 1.0e-3_wp, &
                       'Kelvin far field, Px')
   end subroutine kelvin_far

   subroutine cavity(fix)
      logical, intent(in) :: fix
      integer, parameter :: n = 256
      real(wp), parameter :: r = 5.0_wp, ur = 1.0e-3_wp, theta = 1.0e-4_wp
      real(wp) :: xc(n), yc(n), u(2*n), f(2*n), p, side, fn, torque, ang
      integer :: ca(n), cb(n), i
      real(wp), allocatable :: k(:, :)
      type(error_t), allocatable :: error
      character(len=20) :: tag
      tag = merge(' (BE FIX)  ', ' (no FIX)  ', fix)
      do i = 1, n
         ! clockwise: decreasing angle
         ang = -2.0_wp*pi*real(i - 1, wp)/real(n, wp)
         xc(i) = r*cos(ang)
         yc(i) = r*sin(ang)
         ca(i) = i
         cb(i) = mod(i, n) + 1
      end do
      call be_stiffness(xc, yc, ca, cb, g, nu, fix, 0.0_wp, -60.0_wp, 70.0_wp, 0.0_wp, k, error)
      call check(.not. allocated(error), 'cavity stiffness builds'//tag)
      if (allocated(error)) return
      ! radial expansion
      do i = 1, n
         u(2*i - 1) = ur*xc(i)/r
         u(2*i) = ur*yc(i)/r
      end do
      f = -matmul(k, u)
      p = 2.0_wp*g*ur/r
      side = 2.0_wp*r*sin(pi/real(n, wp))
      fn = 0.0_wp
      do i = 1, n
         fn = fn + (f(2*i - 1)*xc(i) + f(2*i)*yc(i))/r
      end do
      ! inward force on the model: -p times the perimeter of the polygon
      call check_close(fn/(p*n*side), -1.0_wp, 1.0e-2_wp, 'cavity expansion: p = 2 G ur / R'//tag)
      ! a regular polygon: every corner alike (round-off only)
      call check_close(maxval(abs(sqrt(f(1::2)**2 + f(2::2)**2) - abs(fn)/n))/(abs(fn)/n), &
                       0.0_wp, 1.0e-8_wp, 'cavity expansion: same force at every corner'//tag)
      ! rigid translation: free without FIX; with FIX the far field resists
      ! it (the fixed points stay), with a force against the motion
      u(1::2) = ur
      u(2::2) = 0.0_wp
      f = -matmul(k, u)
      if (fix) then
         call check(sum(f(1::2)) < -0.1_wp*p*side, 'cavity translation resisted with BE FIX'//tag)
      else
         call check_close(sum(f(1::2))/(p*n*side), 0.0_wp, 1.0e-9_wp, &
                          'cavity translation free without BE FIX (x)'//tag)
         call check_close(sum(f(2::2))/(p*n*side), 0.0_wp, 1.0e-9_wp, &
                          'cavity translation free without BE FIX (y)'//tag)
      end if
      ! rigid rotation theta (counter-clockwise)
      do i = 1, n
         u(2*i - 1) = -theta*yc(i)
         u(2*i) = theta*xc(i)
      end do
      f = -matmul(k, u)
      torque = 0.0_wp
      do i = 1, n
         torque = torque + xc(i)*f(2*i) - yc(i)*f(2*i - 1)
      end do
      call check_close(torque/(4.0_wp*pi*g*r*r*theta), -1.0_wp, 2.0e-2_wp, &
                       'cavity rotation: torque 4 pi G R^2 theta'//tag)
   end subroutine cavity

   !> Exact field (check 4): unit line loads +x on |x - 15| < 5, y = 6.5 and
   !> -x on y = 5.5 (scaled by 1e6), displacement and stress at (x, y).
   subroutine pair_field(x, y, u, s)
      real(wp), intent(in) :: x, y
      real(wp), intent(out) :: u(2), s(3)
      real(wp) :: ul(2, 2), sl(3, 2)
      call line_load_field(x - 15.0_wp, y - 6.5_wp, 5.0_wp, g, nu, ul, sl)
      u = ul(:, 1)
      s = sl(:, 1)
      call line_load_field(x - 15.0_wp, y - 5.5_wp, 5.0_wp, g, nu, ul, sl)
      u = 1.0e6_wp*(u - ul(:, 1))
      s = 1.0e6_wp*(s - sl(:, 1))
   end subroutine pair_field

   subroutine rectangle(fix)
      logical, intent(in) :: fix
      real(wp), parameter :: hs(2) = [1.5_wp, 0.5_wp]
      real(wp), parameter :: gp(4) = [-0.8611363115940526_wp, -0.3399810435848563_wp, &
                                       0.3399810435848563_wp, 0.8611363115940526_wp]
      real(wp), parameter :: gw(4) = [0.3478548451374538_wp, 0.6521451548625461_wp, &
                                       0.6521451548625461_wp, 0.3478548451374538_wp]
      real(wp), allocatable :: xc(:), yc(:), uu(:), fr(:), fk(:), k(:, :)
      integer, allocatable :: ca(:), cb(:)
      type(error_t), allocatable :: error
      real(wp) :: err(2), u(2), s(3), c(2), t, len, px, py, nxo, nyo, tr(2)
      integer :: ih, n, nx, ny, i, e, q, a, b
      character(len=20) :: tag
      tag = merge(' (BE FIX)  ', ' (no FIX)  ', fix)
      do ih = 1, 2
         nx = nint(30.0_wp/hs(ih))
         ny = nint(12.0_wp/hs(ih))
         n = 2*(nx + ny)
         if (allocated(xc)) deallocate (xc, yc, ca, cb, uu, fr, fk)
         allocate (xc(n), yc(n), ca(n), cb(n), uu(2*n), fr(2*n), fk(2*n))
         ! clockwise from (0, 0): up the left side, along the top, down, back
         i = 0
         do e = 0, ny - 1
            i = i + 1; xc(i) = 0.0_wp; yc(i) = 12.0_wp*e/ny
         end do
         do e = 0, nx - 1
            i = i + 1; xc(i) = 30.0_wp*e/nx; yc(i) = 12.0_wp
         end do
         do e = 0, ny - 1
            i = i + 1; xc(i) = 30.0_wp; yc(i) = 12.0_wp - 12.0_wp*e/ny
         end do
         do e = 0, nx - 1
            i = i + 1; xc(i) = 30.0_wp - 30.0_wp*e/nx; yc(i) = 0.0_wp
         end do
         do i = 1, n
            ca(i) = i
            cb(i) = mod(i, n) + 1
         end do
         ! with FIX the fixed points stay: the exact field plus the rigid
         ! translation that brings them to rest (no traction)
         c = 0.0_wp
         if (fix) then
            call pair_field(6.0_wp, -1.0_wp, u, s)
            c(1) = -u(1)
            call pair_field(35.0_wp, 0.0_wp, u, s)
            c(2) = -u(2)
         end if
         do i = 1, n
            call pair_field(xc(i), yc(i), u, s)
            uu(2*i - 1:2*i) = u + c
         end do
         call be_stiffness(xc, yc, ca, cb, g, nu, fix, 6.0_wp, -1.0_wp, 35.0_wp, 0.0_wp, k, error)
         call check(.not. allocated(error), 'rectangle stiffness builds'//tag)
         if (allocated(error)) return
         fk = -matmul(k, uu)
         if (.not. fix) then
            ! without BE FIX nothing holds the model's translation, so the far
            ! field's corner forces of any displacement, here a rough one,
            ! must sum to zero, or the model drifts away (before the fix
            ! their sum was the midpoint rule's error in the far field's
            ! traction integral: 1.1e-2 and 4.4e-4 of the sum of their sizes
            ! at h = 1.5 and 0.5)
            call random_number(fr)
            fr = -matmul(k, fr - 0.5_wp)
            call check(abs(sum(fr(1::2))) < 1.0e-9_wp*sum(abs(fr)) .and. &
                       abs(sum(fr(2::2))) < 1.0e-9_wp*sum(abs(fr)), &
                       'rectangle: no net force without BE FIX'//trim(tag)//', h = '// &
                       merge('1.5', '0.5', ih == 1))
         end if
         fr = 0.0_wp
         do e = 1, n
            a = ca(e)
            b = cb(e)
            len = hypot(xc(b) - xc(a), yc(b) - yc(a))
            nxo = -(yc(b) - yc(a))/len    ! outward normal: left of the clockwise edge
            nyo = (xc(b) - xc(a))/len
            do q = 1, 4
               t = 0.5_wp*(gp(q) + 1.0_wp)
               px = xc(a) + t*(xc(b) - xc(a))
               py = yc(a) + t*(yc(b) - yc(a))
               call pair_field(px, py, u, s)
               tr = [s(1)*nxo + s(3)*nyo, s(3)*nxo + s(2)*nyo]
               fr(2*a - 1:2*a) = fr(2*a - 1:2*a) + 0.5_wp*len*gw(q)*(1.0_wp - t)*tr
               fr(2*b - 1:2*b) = fr(2*b - 1:2*b) + 0.5_wp*len*gw(q)*t*tr
            end do
         end do
         err(ih) = abs(dot_product(uu, fk)/dot_product(uu, fr) - 1.0_wp)
         call check(err(ih) < 1.0e-2_wp, 'rectangle: work of the far field within 1 % of the exact'// &
                    trim(tag)//', h = '//merge('1.5', '0.5', ih == 1))
      end do
      call check(err(2) <= err(1), 'rectangle: the work error does not grow with refinement'//tag)
   end subroutine rectangle

end program test_be
