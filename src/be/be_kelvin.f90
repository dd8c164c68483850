!> Elastic far field by boundary elements (manual Section 3, "Boundary
!> Element Representation of the Far Field", Eq. 29: F = -K u).
!>
!> The far field is an infinite elastic plane (plane strain, shear modulus G,
!> Poisson's ratio nu) whose boundary is the model's outer boundary. It is
!> discretised by the fictitious-stress method: each boundary element (a
!> straight free edge of a block, corner a -> corner b, clockwise around the
!> model) carries a uniform fictitious traction P = (Ps, Pn) in its own frame
!> (s along the edge, n the outward normal of the model, pointing into the
!> far field). The displacement and stress of a uniform line load over
!> |s| < a in an infinite plane (Kelvin's solution integrated over the
!> element) are written with
!>
!>   f(x, y) = -1/(4 pi (1 - nu)) [ y (t1 - t2) - (x - a) ln r1 + (x + a) ln r2 ]
!>
!> (t1, t2 the angles atan2(y, x -/+ a), r1, r2 the distances to the element
!> ends) and its derivatives:
!>
!>   ux = [Px ((3 - 4 nu) f + y f,y) - Py y f,x] / (2 G)
!>   uy = [-Px y f,x + Py ((3 - 4 nu) f - y f,y)] / (2 G)
!>   sxx = Px ((3 - 2 nu) f,x + y f,xy) + Py (2 nu f,y + y f,yy)
!>   syy = Px (-(1 - 2 nu) f,x - y f,xy) + Py (2 (1 - nu) f,y - y f,yy)
!>   sxy = Px (2 (1 - nu) f,y + y f,yy) + Py ((1 - 2 nu) f,x - y f,xy)
!>
!> (far from the element u tends to the 2-D Kelvin solution of a point force
!> 2 a P; tests/unit/test_be.f90 checks the stresses against the strains of
!> the displacements and the whole matrix against a pressurised circular
!> cavity, u_r = p R / (2 G)).
!>
!> Stiffness (be_stiffness): the midpoint displacement of each element is
!> the mean of its two corners' displacements; the fictitious tractions
!> that produce those midpoint displacements are solved for (LAPACK dgesv),
!> and the traction sigma.n of the far field at each midpoint, on the far
!> field's side, times half the element length goes to each of its two
!> corners. The displacement field carries an unknown rigid translation
!> (cx, cy). With BE FIX the two conditions ux(xh, yh) = 0 and
!> uy(xv, yv) = 0 at the fixed points set it (the far field may then carry a
!> net force, resisted through the logarithm of Kelvin's solution). Without
!> BE FIX the fictitious tractions carry no net force, so the displacement
!> is bounded and tends to (cx, cy) far away: a rigid translation of the
!> model costs nothing, as with stress boundaries; the lumped corner forces
!> are then cleared of the net force the midpoint rule leaves
!> (remove_net_force), which drove such models away. (Letting the tractions
!> carry a net force without a reference point makes the translation
!> stiffness depend on the unit of length through ln r, negative for
!> boundaries larger than about one unit: the model ran away.) The result is K (2 nc x 2 nc, nc the
!> corners of the elements, dofs 2i-1 = x and 2i = y of corner i) with the
!> force on the model F = -K (u - u0).
module be_kelvin
   use core_constants, only: pi
   use core_kinds, only: wp
   use core_error, only: error_t, set_error
   use be_lapack, only: solve_dense_multi
   use be_halfplane, only: element_complement
   implicit none
   private
   public :: line_load_field, be_stiffness, element_influence, be_field


contains

   !> Displacement (ux, uy) and stress (sxx, syy, sxy) at local point (x, y)
   !> of a unit traction component on the element |x| < a, y = 0: column 1
   !> for Px = 1, column 2 for Py = 1. y = +0 on the element gives the side
   !> y > 0.
   pure subroutine line_load_field(x, y, a, g, nu, u, s)
      real(wp), intent(in) :: x, y, a, g, nu
      real(wp), intent(out) :: u(2, 2), s(3, 2)
      real(wp) :: c, r1s, r2s, t1, t2, f, fx, fy, fxy, fxx, fyy
      c = 1.0_wp/(4.0_wp*pi*(1.0_wp - nu))
      r1s = (x - a)**2 + y**2
      r2s = (x + a)**2 + y**2
      t1 = atan2(y, x - a)
      t2 = atan2(y, x + a)
      f = -c*(y*(t1 - t2) - (x - a)*0.5_wp*log_safe(r1s) + (x + a)*0.5_wp*log_safe(r2s))
      fx = c*0.5_wp*(log_safe(r1s) - log_safe(r2s))
      fy = -c*(t1 - t2)
      fxy = c*(y/max(r1s, tiny(1.0_wp)) - y/max(r2s, tiny(1.0_wp)))
      fxx = c*((x - a)/max(r1s, tiny(1.0_wp)) - (x + a)/max(r2s, tiny(1.0_wp)))
      fyy = -fxx
      ! Px = 1
      u(1, 1) = ((3.0_wp - 4.0_wp*nu)*f + y*fy)/(2.0_wp*g)
      u(2, 1) = -y*fx/(2.0_wp*g)
      s(1, 1) = (3.0_wp - 2.0_wp*nu)*fx + y*fxy
      s(2, 1) = -(1.0_wp - 2.0_wp*nu)*fx - y*fxy
      s(3, 1) = 2.0_wp*(1.0_wp - nu)*fy + y*fyy
      ! Py = 1
      u(1, 2) = -y*fx/(2.0_wp*g)
      u(2, 2) = ((3.0_wp - 4.0_wp*nu)*f - y*fy)/(2.0_wp*g)
      s(1, 2) = 2.0_wp*nu*fy + y*fyy
      s(2, 2) = 2.0_wp*(1.0_wp - nu)*fy - y*fyy
      s(3, 2) = (1.0_wp - 2.0_wp*nu)*fx - y*fxy
   contains
      pure real(wp) function log_safe(q)
         real(wp), intent(in) :: q
         log_safe = log(max(q, tiny(1.0_wp)))
      end function log_safe
   end subroutine line_load_field

   !> Influence of element j's unit global tractions (column 1: x, 2: y) on
   !> the global displacement u(2, 2) and stress s(3, 2) (sxx, syy, sxy) at
   !> point (px, py). Element j: midpoint (mx, my), unit tangent (tx, ty),
   !> normal (nx, ny) = (-ty, tx), half length a. `self`: the point is the
   !> element's own midpoint (taken on the side of n). `half`: the far field
   !> is the half plane y < 0 with a free surface y = 0 (be_halfplane adds
   !> the complement of Melan's solution to Kelvin's).
   pure subroutine element_influence(px, py, mx, my, tx, ty, a, g, nu, self, u, s, half)
      real(wp), intent(in) :: px, py, mx, my, tx, ty, a, g, nu
      logical, intent(in) :: self
      real(wp), intent(out) :: u(2, 2), s(3, 2)
      logical, intent(in), optional :: half
      real(wp) :: xl, yl, ul(2, 2), sl(3, 2), r(2, 2), sg(2, 2), st(2, 2), uc(2, 2), sc(3, 2)
      integer :: k
      if (self) then
         xl = 0.0_wp; yl = 0.0_wp
      else
         xl = (px - mx)*tx + (py - my)*ty
         yl = (px - mx)*(-ty) + (py - my)*tx
      end if
      call line_load_field(xl, yl, a, g, nu, ul, sl)
      ! r: columns = local axes in global coordinates (s, n)
      r(:, 1) = [tx, ty]
      r(:, 2) = [-ty, tx]
      ! a global unit load e_k has local components r(k, :) (row k of r)
      do k = 1, 2
         ! local response to local load (r(k,1), r(k,2))
         u(:, k) = matmul(r, ul(:, 1)*r(k, 1) + ul(:, 2)*r(k, 2))
         st(1, 1) = sl(1, 1)*r(k, 1) + sl(1, 2)*r(k, 2)
         st(2, 2) = sl(2, 1)*r(k, 1) + sl(2, 2)*r(k, 2)
         st(1, 2) = sl(3, 1)*r(k, 1) + sl(3, 2)*r(k, 2)
         st(2, 1) = st(1, 2)
         sg = matmul(r, matmul(st, transpose(r)))
         s(:, k) = [sg(1, 1), sg(2, 2), sg(1, 2)]
      end do
      if (present(half)) then
         if (half) then
            call element_complement(px, py, mx - a*tx, my - a*ty, mx + a*tx, my + a*ty, g, nu, &
                                    uc, sc)
            u = u + uc
            s = s + sc
         end if
      end if
   end subroutine element_influence

   !> Displacement u(2) and stress s(3) (sxx, syy, sxy) at (px, py) of the
   !> far field whose elements (midpoints mx, my, unit tangents tx, ty, half
   !> lengths ha) carry the fictitious tractions p(2 ne) (global x, y), plus
   !> the translation (cx, cy).
   pure subroutine be_field(px, py, mx, my, tx, ty, ha, p, cx, cy, g, nu, half, u, s)
      real(wp), intent(in) :: px, py, mx(:), my(:), tx(:), ty(:), ha(:), p(:), cx, cy, g, nu
      logical, intent(in) :: half
      real(wp), intent(out) :: u(2), s(3)
      real(wp) :: ue(2, 2), se(3, 2)
      integer :: j
      u = [cx, cy]
      s = 0.0_wp
      do j = 1, size(mx)
         call element_influence(px, py, mx(j), my(j), tx(j), ty(j), ha(j), g, nu, .false., ue, se, &
                                half)
         u = u + matmul(ue, p(2*j - 1:2*j))
         s = s + matmul(se, p(2*j - 1:2*j))
      end do
   end subroutine be_field

   !> Far-field stiffness of elements e = 1..ne from corner ca(e) to cb(e)
   !> (indices 1..nc into xc, yc; clockwise around the model, so the far
   !> field lies to the left). fix: use the BE FIX points (xh, yh) and
   !> (xv, yv). kmat(2 nc, 2 nc): the force on the model is -kmat (u - u0).
   !> half: the half plane y < 0 (BE HALF). sol (optional, 2 ne + 2 x 2 nc):
   !> the fictitious tractions and the translation (cx, cy) per unit corner
   !> displacement (PRINT BEBOUND, BEINT and the tests evaluate the field
   !> with be_field from them).
   subroutine be_stiffness(xc, yc, ca, cb, g, nu, fix, xh, yh, xv, yv, kmat, error, half, sol)
      real(wp), intent(in) :: xc(:), yc(:)
      integer, intent(in) :: ca(:), cb(:)
      real(wp), intent(in) :: g, nu, xh, yh, xv, yv
      logical, intent(in) :: fix
      real(wp), allocatable, intent(out) :: kmat(:, :)
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: half
      real(wp), allocatable, intent(out), optional :: sol(:, :)
      logical :: hp
      integer :: ne, nc, nu_, i, j, e
      real(wp), allocatable :: mx(:), my(:), tx(:), ty(:), ha(:), amat(:, :), rhs(:, :), trac(:, :)
      real(wp) :: u(2, 2), s(3, 2), l
      hp = .false.
      if (present(half)) hp = half
      ne = size(ca)
      nc = size(xc)
      if (ne == 0) then
         call set_error(error, 'no boundary elements')
         return
      end if
      allocate (mx(ne), my(ne), tx(ne), ty(ne), ha(ne))
      do e = 1, ne
         l = hypot(xc(cb(e)) - xc(ca(e)), yc(cb(e)) - yc(ca(e)))
         if (l <= 0.0_wp) then
            call set_error(error, 'a boundary element has zero length')
            return
         end if
         mx(e) = 0.5_wp*(xc(ca(e)) + xc(cb(e)))
         my(e) = 0.5_wp*(yc(ca(e)) + yc(cb(e)))
         tx(e) = (xc(cb(e)) - xc(ca(e)))/l
         ty(e) = (yc(cb(e)) - yc(ca(e)))/l
         ha(e) = 0.5_wp*l
      end do
      ! unknowns: 2 ne fictitious tractions and the translation (cx, cy)
      nu_ = 2*ne + 2
      allocate (amat(nu_, nu_), rhs(nu_, 2*nc), trac(2*ne, 2*ne))
      amat = 0.0_wp
      rhs = 0.0_wp
      do i = 1, ne
         do j = 1, ne
            call element_influence(mx(i), my(i), mx(j), my(j), tx(j), ty(j), ha(j), g, nu, &
                                   i == j, u, s, hp)
            amat(2*i - 1:2*i, 2*j - 1:2*j) = u
            ! traction sigma.n at midpoint i, n = outward normal of the model
            trac(2*i - 1, 2*j - 1:2*j) = s(1, :)*(-ty(i)) + s(3, :)*tx(i)
            trac(2*i, 2*j - 1:2*j) = s(3, :)*(-ty(i)) + s(2, :)*tx(i)
         end do
         amat(2*i - 1, 2*ne + 1) = 1.0_wp
         amat(2*i, 2*ne + 2) = 1.0_wp
         ! midpoint displacement = mean of the two corners
         rhs(2*i - 1, 2*ca(i) - 1) = rhs(2*i - 1, 2*ca(i) - 1) + 0.5_wp
         rhs(2*i - 1, 2*cb(i) - 1) = rhs(2*i - 1, 2*cb(i) - 1) + 0.5_wp
         rhs(2*i, 2*ca(i)) = rhs(2*i, 2*ca(i)) + 0.5_wp
         rhs(2*i, 2*cb(i)) = rhs(2*i, 2*cb(i)) + 0.5_wp
      end do
      if (fix) then
         do j = 1, ne
            call element_influence(xh, yh, mx(j), my(j), tx(j), ty(j), ha(j), g, nu, .false., u, s, &
                                   hp)
            amat(2*ne + 1, 2*j - 1:2*j) = u(1, :)
            call element_influence(xv, yv, mx(j), my(j), tx(j), ty(j), ha(j), g, nu, .false., u, s, &
                                   hp)
            amat(2*ne + 2, 2*j - 1:2*j) = u(2, :)
         end do
         amat(2*ne + 1, 2*ne + 1) = 1.0_wp
         amat(2*ne + 2, 2*ne + 2) = 1.0_wp
      else
         ! no net force on the far field: its displacement stays bounded and
         ! tends to (cx, cy) at infinity, so a rigid translation is free
         do j = 1, ne
            amat(2*ne + 1, 2*j - 1) = ha(j)
            amat(2*ne + 2, 2*j) = ha(j)
         end do
      end if
      call solve_dense_multi(amat, rhs, error)
      if (allocated(error)) return
      if (present(sol)) sol = rhs
      ! rhs(1:2ne, :) = fictitious tractions per unit corner displacement;
      ! tractions at the midpoints, lumped half to each end corner
      rhs(1:2*ne, :) = matmul(trac, rhs(1:2*ne, :))
      allocate (kmat(2*nc, 2*nc))
      kmat = 0.0_wp
      do i = 1, ne
         kmat(2*ca(i) - 1:2*ca(i), :) = kmat(2*ca(i) - 1:2*ca(i), :) - ha(i)*rhs(2*i - 1:2*i, :)
         kmat(2*cb(i) - 1:2*cb(i), :) = kmat(2*cb(i) - 1:2*cb(i), :) - ha(i)*rhs(2*i - 1:2*i, :)
      end do
      if (.not. fix) call remove_net_force(kmat, ca, cb, ha)
   end subroutine be_stiffness

   !> Without BE FIX nothing holds the model's translation, so the far field
   !> must exert no net force whatever the corners' displacements. Its
   !> fictitious tractions carry none, but the midpoint tractions lumped to
   !> the corners sum to zero only to the accuracy of the midpoint rule (1 %
   !> of the forces' sizes for a rough displacement on 1.5 m elements, 0.04 %
   !> on 0.5 m ones; tests/unit/test_be.f90); that remainder, small but
   !> steady, drove a model held by the far field away at a constant
   !> acceleration once DAMP AUTO had let it settle (a Kirsch hole,
   !> verification.closed_forms_fields). Each column's net force is taken
   !> off as a uniform traction: from each corner its share of the boundary
   !> length. A rigid translation still costs nothing (K t = 0 before and
   !> after).
   subroutine remove_net_force(kmat, ca, cb, ha)
      real(wp), intent(inout) :: kmat(:, :)
      integer, intent(in) :: ca(:), cb(:)
      real(wp), intent(in) :: ha(:)
      real(wp), allocatable :: w(:)
      real(wp) :: fx, fy
      integer :: e, j
      allocate (w(size(kmat, 1)/2))
      w = 0.0_wp
      do e = 1, size(ca)
         w(ca(e)) = w(ca(e)) + ha(e)
         w(cb(e)) = w(cb(e)) + ha(e)
      end do
      w = w/sum(w)
      do j = 1, size(kmat, 2)
         fx = sum(kmat(1::2, j))
         fy = sum(kmat(2::2, j))
         kmat(1::2, j) = kmat(1::2, j) - w*fx
         kmat(2::2, j) = kmat(2::2, j) - w*fy
      end do
   end subroutine remove_net_force

end module be_kelvin
