!> The half-plane part of the boundary-element kernel (BE HALF; UDEC manual
!> (ICG1.5, 1989), Section 4.5, BE: "half-plane solution for boundary
!> element domain, assuming surface at y = 0"; Section 3, "Boundary Element
!> Representation of the Far Field": the half-plane formulation of Lemos
!> (1983)).
!>
!> The far field is the elastic half plane y < 0 whose surface y = 0 is free
!> of traction. The field of a point force F = Fx + i Fy at z0 (Im z0 < 0)
!> in it is Melan's (1932) solution: Kelvin's infinite-plane field plus a
!> complementary field, regular in y <= 0, whose singularities lie at the
!> image point conj(z0). Derived here with Muskhelishvili's complex
!> potentials (Muskhelishvili, "Some basic problems of the mathematical
!> theory of elasticity", 1953, Sections 32-33 and 56; Telles and Brebbia
!> (1981), "Boundary element solution for half-plane problems", Int. J.
!> Solids Struct. 17, give the same field in Cartesian form):
!>
!>   2 G (ux + i uy) = kappa phi - z conj(phi') - conj(psi)
!>   sxx + syy = 4 Re phi',   syy - sxx + 2 i sxy = 2 (conj(z) phi'' + psi')
!>
!> with kappa = 3 - 4 nu (plane strain). Kelvin's force at z0:
!> phi0 = -c F log(z - z0), psi0 = c kappa conj(F) log(z - z0)
!> + c F conj(z0) / (z - z0), c = 1 / (2 pi (1 + kappa)). Writing
!> fbar(z) = conj(f(conj z)), the traction-free condition on the real axis,
!> phi + t conj(phi') + conj(psi) = 0, is met by the complement
!>
!>   phi1 = -z phi0bar'(z) - psi0bar(z),   psi1 = -phi0bar(z) - z phi1'(z),
!>
!> both regular in the lower half plane (their singularities are at
!> conj(z0)); with w = z - conj(z0) and y0 = Im z0:
!>
!>   phi1  = c conj(F) (1 - 2 i y0 / w) - c kappa F log w
!>   phi1' = 2 i y0 c conj(F) / w^2 - c kappa F / w
!>   psi1  = c conj(F) log w - z phi1'
!>
!> The element integral of the Kelvin part is be_kelvin's closed form; the
!> complement is integrated here by Gauss-Legendre quadrature, the element
!> bisected until each piece is shorter than its distance from the image of
!> the field point (so pieces near the surface get short). tests/unit/
!> test_be_half.f90 checks the surface is traction free and the field obeys
!> Hooke's law.
module be_halfplane
   use core_constants, only: pi
   use core_kinds, only: wp
   implicit none
   private
   public :: melan_complement, element_complement

   ! 8-point Gauss-Legendre on (-1, 1)
   real(wp), parameter :: gx(8) = [-0.9602898564975363_wp, -0.7966664774136267_wp, &
                                    -0.5255324099163290_wp, -0.1834346424956498_wp, &
                                    0.1834346424956498_wp, 0.5255324099163290_wp, &
                                    0.7966664774136267_wp, 0.9602898564975363_wp]
   real(wp), parameter :: gw(8) = [0.1012285362903763_wp, 0.2223810344533745_wp, &
                                    0.3137066458778873_wp, 0.3626837833783620_wp, &
                                    0.3626837833783620_wp, 0.3137066458778873_wp, &
                                    0.2223810344533745_wp, 0.1012285362903763_wp]
   integer, parameter :: max_pieces = 4096

contains

   !> Complementary (surface) part of Melan's field at (x, y) of a unit point
   !> force at (x0, y0), y0 < 0, y <= 0: column 1 for Fx = 1, column 2 for
   !> Fy = 1; u(2, k) displacement, s(3, k) = sxx, syy, sxy.
   pure subroutine melan_complement(x, y, x0, y0, g, nu, u, s)
      real(wp), intent(in) :: x, y, x0, y0, g, nu
      real(wp), intent(out) :: u(2, 2), s(3, 2)
      complex(wp) :: z, w, f, fb, p1, dp1, d2p1, q1, dq1, disp, dev
      complex(wp), parameter :: iu = (0.0_wp, 1.0_wp)
      real(wp) :: kap, c, sum_
      integer :: k
      kap = 3.0_wp - 4.0_wp*nu
      c = 1.0_wp/(2.0_wp*pi*(1.0_wp + kap))
      z = cmplx(x, y, wp)
      w = z - cmplx(x0, -y0, wp)
      do k = 1, 2
         f = merge((1.0_wp, 0.0_wp), (0.0_wp, 1.0_wp), k == 1)
         fb = conjg(f)
         p1 = c*fb*(1.0_wp - 2.0_wp*iu*y0/w) - c*kap*f*log(w)
         dp1 = 2.0_wp*iu*y0*c*fb/w**2 - c*kap*f/w
         d2p1 = -4.0_wp*iu*y0*c*fb/w**3 + c*kap*f/w**2
         q1 = c*fb*log(w) - z*dp1
         dq1 = c*fb/w - dp1 - z*d2p1
         disp = (kap*p1 - z*conjg(dp1) - conjg(q1))/(2.0_wp*g)
         u(1, k) = real(disp, wp)
         u(2, k) = aimag(disp)
         sum_ = 4.0_wp*real(dp1, wp)
         dev = 2.0_wp*(conjg(z)*d2p1 + dq1)
         s(1, k) = 0.5_wp*(sum_ - real(dev, wp))
         s(2, k) = 0.5_wp*(sum_ + real(dev, wp))
         s(3, k) = 0.5_wp*aimag(dev)
      end do
   end subroutine melan_complement

   !> Complement of a unit traction (global x: column 1, y: column 2) spread
   !> uniformly over the element from (xa, ya) to (xb, yb), at (px, py).
   pure subroutine element_complement(px, py, xa, ya, xb, yb, g, nu, u, s)
      real(wp), intent(in) :: px, py, xa, ya, xb, yb, g, nu
      real(wp), intent(out) :: u(2, 2), s(3, 2)
      real(wp) :: t0(max_pieces), t1(max_pieces), ta, tb, tm, len, d, qx, qy, wq
      real(wp) :: uq(2, 2), sq(3, 2)
      integer :: top, i
      len = hypot(xb - xa, yb - ya)
      u = 0.0_wp
      s = 0.0_wp
      top = 1
      t0(1) = 0.0_wp
      t1(1) = 1.0_wp
      do while (top > 0)
         ta = t0(top)
         tb = t1(top)
         top = top - 1
         d = image_distance(px, py, xa + ta*(xb - xa), ya + ta*(yb - ya), &
                            xa + tb*(xb - xa), ya + tb*(yb - ya))
         if ((tb - ta)*len > d .and. top + 2 <= max_pieces .and. (tb - ta)*len > 1.0e-9_wp*len) then
            tm = 0.5_wp*(ta + tb)
            top = top + 1
            t0(top) = ta; t1(top) = tm
            top = top + 1
            t0(top) = tm; t1(top) = tb
            cycle
         end if
         do i = 1, 8
            tm = ta + 0.5_wp*(1.0_wp + gx(i))*(tb - ta)
            qx = xa + tm*(xb - xa)
            qy = ya + tm*(yb - ya)
            wq = 0.5_wp*gw(i)*(tb - ta)*len
            call melan_complement(px, py, qx, qy, g, nu, uq, sq)
            u = u + wq*uq
            s = s + wq*sq
         end do
      end do
   end subroutine element_complement

   !> Distance from (px, py) to the mirror image (y -> -y) of the segment.
   pure real(wp) function image_distance(px, py, xa, ya, xb, yb) result(d)
      real(wp), intent(in) :: px, py, xa, ya, xb, yb
      real(wp) :: dx, dy, t, l2
      dx = xb - xa
      dy = -(yb - ya)
      l2 = dx*dx + dy*dy
      t = 0.0_wp
      if (l2 > 0.0_wp) t = max(0.0_wp, min(1.0_wp, ((px - xa)*dx + (py + ya)*dy)/l2))
      d = hypot(px - (xa + t*dx), py - (-ya + t*dy))
   end function image_distance

end module be_halfplane
