!> Half-plane boundary elements (BE HALF; src/be/be_halfplane.f90).
!> Without an argument (ctest unit.test_be_half):
!>  1. the ground surface is free: at surface points y = 0 the stresses
!>     syy and sxy of an element's full half-plane field (Kelvin closed form
!>     plus the integrated complement) vanish, within 1e-7 of the Kelvin
!>     part alone there (elements at depths 0.5 to 3 lengths, and one
!>     touching the surface);
!>  2. the complement obeys plane-strain Hooke's law (central differences,
!>     1e-5 relative to its largest stress).
!>  3. a deep cavity (centre 50 radii below the surface) in the half plane
!>     answers the infinite plane: Lame's u_r = p R / (2 G) on its wall
!>     needs the pressure p (corner forces p n L within 1 %, as
!>     test_be's cavity).
!> With the argument `hole` (ctest verification.be_half_hole): a circular
!> hole of radius R, centre at depth h = 2 R and 4 R below the free surface,
!> pressurised by p, 128 elements: the displacement of the hole wall and of
!> the ground surface (|x| <= 4 h), relative to the displacement far away,
!> within 3 % of the largest displacement on that line, against the classical
!> solution: Muskhelishvili's potentials on the annulus alpha < |zeta| < 1
!> that the map z = -i a (1 + zeta) / (1 - zeta) makes of the half plane with
!> the hole (Verruijt 1997, "A complex variable solution for a deforming
!> circular tunnel in an elastic half-plane", Int. J. Numer. Anal. Meth.
!> Geomech. 21; Jeffery 1920 for the stresses), its Laurent coefficients
!> found here by least squares on both circles (residual printed; checked
!> against Lame at h = 50 R within 0.1 %).
program test_be_half
   use core_kinds, only: wp
   use core_error, only: error_t
   use be_kelvin, only: line_load_field, be_stiffness, element_influence, be_field
   use be_halfplane, only: melan_complement, element_complement
   use testing, only: check, check_close, testing_finish
   implicit none
   real(wp), parameter :: pi = 3.14159265358979323846_wp
   real(wp), parameter :: g = 1.0e9_wp, nu = 0.25_wp
   character(len=16) :: arg

   interface
      subroutine dgels(trans, m, n, nrhs, a, lda, b, ldb, work, lwork, info)
         import :: wp
         character(len=1), intent(in) :: trans
         integer, intent(in) :: m, n, nrhs, lda, ldb, lwork
         real(wp), intent(inout) :: a(lda, *), b(ldb, *)
         real(wp), intent(inout) :: work(*)
         integer, intent(out) :: info
      end subroutine dgels
   end interface

   arg = ''
   if (command_argument_count() > 0) call get_command_argument(1, arg)
   if (trim(arg) == 'hole') then
      call reference_check()
      call hole(2.0_wp)
      call hole(4.0_wp)
   else
      call free_surface(0.3_wp, -1.2_wp, 1.1_wp, -0.7_wp)
      call free_surface(-2.0_wp, -3.0_wp, -1.5_wp, -3.5_wp)
      call free_surface(0.0_wp, 0.0_wp, 0.0_wp, -1.0_wp)
      call hooke_complement(0.4_wp, -0.3_wp)
      call hooke_complement(-1.0_wp, -2.0_wp)
      call deep_cavity()
   end if
   call testing_finish()

contains

   subroutine free_surface(xa, ya, xb, yb)
      real(wp), intent(in) :: xa, ya, xb, yb
      real(wp) :: mx, my, tx, ty, a, u(2, 2), s(3, 2), uk(2, 2), sk(3, 2), x, scale
      integer :: i
      character(len=80) :: label
      a = 0.5_wp*hypot(xb - xa, yb - ya)
      mx = 0.5_wp*(xa + xb); my = 0.5_wp*(ya + yb)
      tx = (xb - xa)/(2.0_wp*a); ty = (yb - ya)/(2.0_wp*a)
      do i = -6, 6
         x = mx + 0.7_wp*i + 0.05_wp
         call element_influence(x, 0.0_wp, mx, my, tx, ty, a, g, nu, .false., uk, sk)
         call element_influence(x, 0.0_wp, mx, my, tx, ty, a, g, nu, .false., u, s, .true.)
         scale = maxval(abs(sk))
         write (label, '(a,f6.2,a,f6.2)') 'free surface: element at y', my, ', x', x
         call check(abs(s(2, 1)) < 1.0e-7_wp*scale .and. abs(s(3, 1)) < 1.0e-7_wp*scale .and. &
                    abs(s(2, 2)) < 1.0e-7_wp*scale .and. abs(s(3, 2)) < 1.0e-7_wp*scale, &
                    trim(label))
      end do
   end subroutine free_surface

   subroutine hooke_complement(x, y)
      real(wp), intent(in) :: x, y
      real(wp) :: h, u(2, 2), s(3, 2), upx(2, 2), umx(2, 2), upy(2, 2), umy(2, 2), sd(3, 2)
      real(wp) :: exx, eyy, exy, lam, smax
      real(wp), parameter :: xa = 0.2_wp, ya = -1.0_wp, xb = 0.9_wp, yb = -1.4_wp
      integer :: k
      h = 1.0e-5_wp
      call element_complement(x, y, xa, ya, xb, yb, g, nu, u, s)
      call element_complement(x + h, y, xa, ya, xb, yb, g, nu, upx, sd)
      call element_complement(x - h, y, xa, ya, xb, yb, g, nu, umx, sd)
      call element_complement(x, y + h, xa, ya, xb, yb, g, nu, upy, sd)
      call element_complement(x, y - h, xa, ya, xb, yb, g, nu, umy, sd)
      lam = 2.0_wp*g*nu/(1.0_wp - 2.0_wp*nu)
      do k = 1, 2
         exx = (upx(1, k) - umx(1, k))/(2.0_wp*h)
         eyy = (upy(2, k) - umy(2, k))/(2.0_wp*h)
         exy = 0.5_wp*((upy(1, k) - umy(1, k))/(2.0_wp*h) + (upx(2, k) - umx(2, k))/(2.0_wp*h))
         smax = maxval(abs(s(:, k)))
         call check_close(((lam + 2.0_wp*g)*exx + lam*eyy)/smax, s(1, k)/smax, 1.0e-5_wp, &
                          'complement Hooke sxx')
         call check_close((lam*exx + (lam + 2.0_wp*g)*eyy)/smax, s(2, k)/smax, 1.0e-5_wp, &
                          'complement Hooke syy')
         call check_close(2.0_wp*g*exy/smax, s(3, k)/smax, 1.0e-5_wp, 'complement Hooke sxy')
      end do
   end subroutine hooke_complement

   !> Corners of n elements on the circle (0, -h) radius r, clockwise.
   subroutine circle(n, r, h, xc, yc, ca, cb)
      integer, intent(in) :: n
      real(wp), intent(in) :: r, h
      real(wp), allocatable, intent(out) :: xc(:), yc(:)
      integer, allocatable, intent(out) :: ca(:), cb(:)
      integer :: i
      allocate (xc(n), yc(n), ca(n), cb(n))
      do i = 1, n
         xc(i) = r*cos(-2.0_wp*pi*(i - 1)/n)
         yc(i) = -h + r*sin(-2.0_wp*pi*(i - 1)/n)
         ca(i) = i
         cb(i) = mod(i, n) + 1
      end do
   end subroutine circle

   !> Corner forces of a pressure p on the far field (outward from the hole).
   subroutine pressure_forces(xc, yc, ca, cb, p, f)
      real(wp), intent(in) :: xc(:), yc(:), p
      integer, intent(in) :: ca(:), cb(:)
      real(wp), intent(out) :: f(:)
      integer :: e
      real(wp) :: dx, dy
      f = 0.0_wp
      do e = 1, size(ca)
         dx = xc(cb(e)) - xc(ca(e))
         dy = yc(cb(e)) - yc(ca(e))
         ! outward normal of the hole (into the far field), left of a clockwise edge
         associate (fx => -0.5_wp*p*dy, fy => 0.5_wp*p*dx)
            f(2*ca(e) - 1) = f(2*ca(e) - 1) - fx
            f(2*ca(e)) = f(2*ca(e)) - fy
            f(2*cb(e) - 1) = f(2*cb(e) - 1) - fx
            f(2*cb(e)) = f(2*cb(e)) - fy
         end associate
      end do
   end subroutine pressure_forces

   subroutine deep_cavity()
      integer, parameter :: n = 256
      real(wp), parameter :: r = 1.0_wp, h = 50.0_wp, ur = 1.0e-3_wp
      real(wp), allocatable :: xc(:), yc(:), k(:, :), u(:), f(:), fp(:)
      integer, allocatable :: ca(:), cb(:)
      type(error_t), allocatable :: error
      real(wp) :: p
      integer :: i
      call circle(n, r, h, xc, yc, ca, cb)
      call be_stiffness(xc, yc, ca, cb, g, nu, .false., 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, k, error, &
                        half=.true.)
      call check(.not. allocated(error), 'deep cavity: stiffness built')
      if (allocated(error)) return
      allocate (u(2*n), f(2*n), fp(2*n))
      do i = 1, n
         u(2*i - 1) = ur*xc(i)/r
         u(2*i) = ur*(yc(i) + h)/r
      end do
      f = -matmul(k, u)
      p = 2.0_wp*g*ur/r
      ! the far field's force on the hole contents: -(pressure on the far field)
      call pressure_forces(xc, yc, ca, cb, p, fp)
      call check_close(maxval(abs(f - fp))/maxval(abs(fp)), 0.0_wp, 0.01_wp, &
                       'deep cavity (h = 50 R) in the half plane: Lame pressure (1 %)')
   end subroutine deep_cavity

   ! ---------------------------------------------------------------------
   ! Classical solution: pressurised hole in the half plane y < 0.
   ! ---------------------------------------------------------------------

   !> Coefficients of phi, psi (Laurent, k = -nk..nk) for hole depth h,
   !> radius r, pressure p; residual: largest boundary-condition misfit
   !> relative to p r.
   subroutine verruijt(h, r, p, nk, a, alpha, cphi, cpsi, residual)
      real(wp), intent(in) :: h, r, p
      integer, intent(in) :: nk
      real(wp), intent(out) :: a, alpha, residual
      complex(wp), intent(out) :: cphi(-nk:nk), cpsi(-nk:nk)
      integer :: m, ncol, nrow, i, kk, col, row, info, lwork, b
      real(wp), allocatable :: amat(:, :), rhs(:, :), work(:), acopy(:, :), rcopy(:)
      complex(wp) :: zeta, rr, col_val, fz
      complex(wp), parameter :: iu = (0.0_wp, 1.0_wp)
      real(wp) :: rho, th
      alpha = h/r - sqrt((h/r)**2 - 1.0_wp)
      a = h*(1.0_wp - alpha**2)/(1.0_wp + alpha**2)
      m = 8*nk
      ! unknowns: phi_k (k /= 0) re, im; psi_k re, im; hole constant re, im
      ncol = 2*(2*nk) + 2*(2*nk + 1) + 2
      nrow = 2*2*m
      allocate (amat(nrow, ncol), rhs(nrow, 1))
      amat = 0.0_wp
      rhs = 0.0_wp
      row = 0
      do b = 1, 2
         rho = merge(1.0_wp, alpha, b == 1)
         do i = 1, m
            th = 2.0_wp*pi*(i - 0.5_wp)/m
            zeta = rho*exp(iu*th)
            rr = omega(zeta, a)/conjg(domega(zeta, a))
            col = 0
            do kk = -nk, nk
               if (kk == 0) cycle
               ! phi = zeta^k: phi + rr conj(phi') ; then i zeta^k
               col_val = zeta**kk + rr*conjg(kk*zeta**(kk - 1))
               col = col + 1
               amat(row + 1, col) = real(col_val, wp); amat(row + 2, col) = aimag(col_val)
               col_val = iu*zeta**kk + rr*conjg(iu*kk*zeta**(kk - 1))
               col = col + 1
               amat(row + 1, col) = real(col_val, wp); amat(row + 2, col) = aimag(col_val)
            end do
            do kk = -nk, nk
               col_val = conjg(zeta**kk)
               col = col + 1
               amat(row + 1, col) = real(col_val, wp); amat(row + 2, col) = aimag(col_val)
               col_val = conjg(iu*zeta**kk)
               col = col + 1
               amat(row + 1, col) = real(col_val, wp); amat(row + 2, col) = aimag(col_val)
            end do
            fz = (0.0_wp, 0.0_wp)
            if (b == 2) then
               ! hole: phi + z conj(phi') + conj(psi) = -p z + C (Muskhelishvili)
               amat(row + 1, col + 1) = -1.0_wp
               amat(row + 2, col + 2) = -1.0_wp
               fz = -p*omega(zeta, a)
            end if
            rhs(row + 1, 1) = real(fz, wp)
            rhs(row + 2, 1) = aimag(fz)
            row = row + 2
         end do
      end do
      acopy = amat
      rcopy = rhs(:, 1)
      lwork = 64*(nrow + ncol)
      allocate (work(lwork))
      call dgels('N', nrow, ncol, 1, amat, nrow, rhs, nrow, work, lwork, info)
      call check(info == 0, 'reference: dgels')
      residual = maxval(abs(matmul(acopy, rhs(1:ncol, 1)) - rcopy))/(p*r)
      col = 0
      cphi = (0.0_wp, 0.0_wp)
      do kk = -nk, nk
         if (kk == 0) cycle
         cphi(kk) = cmplx(rhs(col + 1, 1), rhs(col + 2, 1), wp)
         col = col + 2
      end do
      do kk = -nk, nk
         cpsi(kk) = cmplx(rhs(col + 1, 1), rhs(col + 2, 1), wp)
         col = col + 2
      end do
   end subroutine verruijt

   complex(wp) function omega(zz, a)
      complex(wp), intent(in) :: zz
      real(wp), intent(in) :: a
      omega = -(0.0_wp, 1.0_wp)*a*(1.0_wp + zz)/(1.0_wp - zz)
   end function omega

   complex(wp) function domega(zz, a)
      complex(wp), intent(in) :: zz
      real(wp), intent(in) :: a
      domega = -2.0_wp*(0.0_wp, 1.0_wp)*a/(1.0_wp - zz)**2
   end function domega

   !> Displacement of the classical solution at z (y <= 0, outside the hole),
   !> relative to the displacement far away.
   function ref_disp(z, a, nk, cphi, cpsi) result(u)
      complex(wp), intent(in) :: z
      real(wp), intent(in) :: a
      integer, intent(in) :: nk
      complex(wp), intent(in) :: cphi(-nk:nk), cpsi(-nk:nk)
      real(wp) :: u(2)
      complex(wp), parameter :: iu = (0.0_wp, 1.0_wp)
      complex(wp) :: zeta, v, vinf
      zeta = (z + iu*a)/(z - iu*a)
      v = disp(zeta, a, nk, cphi, cpsi)
      vinf = disp((1.0_wp, 0.0_wp), a, nk, cphi, cpsi)
      u = [real(v - vinf, wp), aimag(v - vinf)]
   end function ref_disp

   !> 2 G (ux + i uy) / (2 G) at zeta.
   complex(wp) function disp(zz, a, nk, cphi, cpsi)
      complex(wp), intent(in) :: zz
      real(wp), intent(in) :: a
      integer, intent(in) :: nk
      complex(wp), intent(in) :: cphi(-nk:nk), cpsi(-nk:nk)
      complex(wp) :: ph, dph, ps, rr
      integer :: k
      real(wp) :: kap
      kap = 3.0_wp - 4.0_wp*nu
      ph = 0; dph = 0; ps = 0
      do k = -nk, nk
         ph = ph + cphi(k)*zz**k
         if (k /= 0) dph = dph + k*cphi(k)*zz**(k - 1)
         ps = ps + cpsi(k)*zz**k
      end do
      ! omega / conj(omega'): zero at zeta = 1 (the point at infinity)
      if (abs(zz - 1.0_wp) < 1.0e-14_wp) then
         rr = 0
      else
         rr = omega(zz, a)/conjg(domega(zz, a))
      end if
      disp = (kap*ph - rr*conjg(dph) - conjg(ps))/(2.0_wp*g)
   end function disp

   !> The classical solution reproduces Lame far from the surface (0.1 %)
   !> and its boundary conditions (residual < 1e-8 p R at h = 2 R, 4 R).
   subroutine reference_check()
      integer, parameter :: nk = 40
      complex(wp) :: cphi(-nk:nk), cpsi(-nk:nk)
      real(wp) :: a, alpha, res, u(2), p, r, h, ur
      integer :: i
      character(len=80) :: label
      p = 1.0e6_wp; r = 1.0_wp
      do i = 1, 3
         h = merge(2.0_wp, merge(4.0_wp, 50.0_wp, i == 2), i == 1)
         call verruijt(h, r, p, nk, a, alpha, cphi, cpsi, res)
         write (label, '(a,f5.1,a,es9.2)') 'reference h/R =', h, ': residual', res
         call check(res < 1.0e-8_wp, trim(label))
      end do
      ! at h = 50 R the wall displacement relative to its mean is Lame's
      u = ref_disp(cmplx(r, -h, wp), a, nk, cphi, cpsi) - ref_disp(cmplx(-r, -h, wp), a, nk, cphi, cpsi)
      ur = p*r/(2.0_wp*g)
      call check_close(0.5_wp*u(1), ur, 1.0e-3_wp, 'reference at h = 50 R: Lame u_r')
   end subroutine reference_check

   !> Pressurised hole at depth h (radius 1): BE HALF against the classical
   !> solution.
   subroutine hole(hr)
      real(wp), intent(in) :: hr
      integer, parameter :: n = 128, nk = 40
      real(wp), parameter :: r = 1.0_wp, p = 1.0e6_wp
      real(wp), allocatable :: xc(:), yc(:), k(:, :), sol(:, :), aug(:, :), f(:, :), u(:), pt(:)
      real(wp), allocatable :: mx(:), my(:), tx(:), ty(:), ha(:)
      integer, allocatable :: ca(:), cb(:)
      type(error_t), allocatable :: error
      complex(wp) :: cphi(-nk:nk), cpsi(-nk:nk)
      real(wp) :: a, alpha, res, h, ur(2), ub(2), umax, emax, cx, cy, x, s(3), l
      integer :: i, e, ne
      character(len=100) :: label
      h = hr*r
      call verruijt(h, r, p, nk, a, alpha, cphi, cpsi, res)
      call circle(n, r, h, xc, yc, ca, cb)
      call be_stiffness(xc, yc, ca, cb, g, nu, .false., 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, k, error, &
                        half=.true., sol=sol)
      call check(.not. allocated(error), 'hole: stiffness built')
      if (allocated(error)) return
      ! K u = f (the pressure on the far field). K alone leaves free the
      ! translation and, n being even, the alternating corner pattern that
      ! moves no element midpoint (in a model the blocks hold both): both
      ! are fixed here by zero mean, then the far field's own translation
      ! (cx, cy) is removed
      allocate (aug(2*n + 4, 2*n + 4), f(2*n + 4, 1))
      aug = 0.0_wp
      aug(1:2*n, 1:2*n) = k
      do i = 1, n
         aug(2*i - 1, 2*n + 1) = 1.0_wp; aug(2*n + 1, 2*i - 1) = 1.0_wp
         aug(2*i, 2*n + 2) = 1.0_wp; aug(2*n + 2, 2*i) = 1.0_wp
         aug(2*i - 1, 2*n + 3) = (-1.0_wp)**i; aug(2*n + 3, 2*i - 1) = (-1.0_wp)**i
         aug(2*i, 2*n + 4) = (-1.0_wp)**i; aug(2*n + 4, 2*i) = (-1.0_wp)**i
      end do
      f = 0.0_wp
      call pressure_forces(xc, yc, ca, cb, -p, f(1:2*n, 1))
      block
         use be_lapack, only: solve_dense_multi
         call solve_dense_multi(aug, f, error)
      end block
      call check(.not. allocated(error), 'hole: solved')
      if (allocated(error)) return
      u = f(1:2*n, 1)
      pt = matmul(sol, u)
      ne = n
      cx = pt(2*ne + 1); cy = pt(2*ne + 2)
      ! hole wall
      umax = 0.0_wp; emax = 0.0_wp
      do i = 1, n
         ur = ref_disp(cmplx(xc(i), yc(i), wp), a, nk, cphi, cpsi)
         ub = [u(2*i - 1) - cx, u(2*i) - cy]
         umax = max(umax, hypot(ur(1), ur(2)))
         emax = max(emax, hypot(ub(1) - ur(1), ub(2) - ur(2)))
      end do
      write (label, '(a,f4.1,a,f6.2,a)') 'hole at h =', hr, ' R: wall displacement error ', &
         100.0_wp*emax/umax, ' % (3 %)'
      call check(emax < 0.03_wp*umax, trim(label))
      print '(a)', trim(label)
      ! ground surface
      allocate (mx(ne), my(ne), tx(ne), ty(ne), ha(ne))
      do e = 1, ne
         l = hypot(xc(cb(e)) - xc(ca(e)), yc(cb(e)) - yc(ca(e)))
         mx(e) = 0.5_wp*(xc(ca(e)) + xc(cb(e))); my(e) = 0.5_wp*(yc(ca(e)) + yc(cb(e)))
         tx(e) = (xc(cb(e)) - xc(ca(e)))/l; ty(e) = (yc(cb(e)) - yc(ca(e)))/l
         ha(e) = 0.5_wp*l
      end do
      umax = 0.0_wp; emax = 0.0_wp
      do i = -20, 20
         x = 0.2_wp*h*i
         ur = ref_disp(cmplx(x, 0.0_wp, wp), a, nk, cphi, cpsi)
         call be_field(x, 0.0_wp, mx, my, tx, ty, ha, pt(1:2*ne), 0.0_wp, 0.0_wp, g, nu, .true., &
                       ub, s)
         umax = max(umax, hypot(ur(1), ur(2)))
         emax = max(emax, hypot(ub(1) - ur(1), ub(2) - ur(2)))
         if (i == 0) print '(a,f4.1,a,2es13.5)', 'surface above h =', hr, ' R: BE / classical uy ', &
            ub(2), ur(2)
      end do
      write (label, '(a,f4.1,a,f6.2,a)') 'hole at h =', hr, ' R: surface displacement error ', &
         100.0_wp*emax/umax, ' % (3 %)'
      call check(emax < 0.03_wp*umax, trim(label))
      print '(a)', trim(label)
   end subroutine hole

end program test_be_half
