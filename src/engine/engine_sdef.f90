!> Simply-deformable (SDEF) blocks (UDEC manual (ICG1.5, 1989), Section 3.2,
!> p. 3-2, and Section 5.2.4, Fig. 5-2; CHANGE SDEF, CONS 1 and 4, DAMP
!> INTERNAL in Section 4.5): besides the three rigid-body modes a block has
!> three modes of uniform strain, exx, eyy and exy (tensor shear), so that a
!> point at offset r from the centroid moves by
!>     u = U + theta x r + E r,   E = [[exx, exy], [exy, eyy]].
!> The rigid modes move as rigid blocks do (engine_rigid); this stage moves
!> the strain modes. Lagrange's equations of the field above, with the
!> contact and boundary forces F at points r and the internal (block) stress
!> sigma (tension positive) acting on the block area A, give
!>     M d2e/dt2 = Q - A s,    e = (exx, eyy, exy),
!>     Q = (sum Fx rx, sum Fy ry, sum (Fx ry + Fy rx))   (the manual's applied
!>         stress times area, KSA, with the shear counted twice),
!>     s = (sxx, syy, 2 sxy),
!>     M = rho [[Ixx, 0, Ixy], [0, Iyy, Ixy], [Ixy, Ixy, Ixx + Iyy]],
!> I.. the second moments of the block about its centroid (Ixx = int x^2 dA).
!> The coupling of the strain modes with the rotation in the kinetic energy
!> (rho (Ixx - Iyy) for exy, rho Ixy for exx and eyy) is dropped: it is zero
!> for a block with Ixx = Iyy and Ixy = 0 (a square, a regular polygon).
!> Central differences as for rigid blocks (Eqs. 24, 25, 28), with the
!> mass-proportional damping of the whole model plus that of DAMP INTERNAL
!> (the manual's ALPB, C1B, C2B) on the strain modes only, and the stiffness-
!> proportional part as a viscous stress beta D de/dt.
!> Elastic (CONS 1): plane-strain Hooke's law, increments of stress from the
!> increments of strain: sxx += (K + 4G/3) dexx + (K - 2G/3) deyy, ...
!> CONS 4 (Griffith, PROPERTY TF): with sp1 >= sp2 the principal stresses,
!> the block fractures when
!>     sp1 >= TF                                  if 3 sp1 + sp2 > 0,
!>     -(sp1 - sp2)^2 / (8 (sp1 + sp2)) >= TF     otherwise
!> (Section 4.5 PROPERTY, CONS = 4); a fractured block (state 4, the
!> manual's KBPLAS "surpassed tension cut-off") keeps no tension: after
!> every step its principal stresses are cut at zero.
!> Strains and stresses are small-strain and turn with their block (the
!> rotation of a step turns both tensors). The block area and mass stay as
!> they were (the centroid of a polygon is where a uniform strain leaves it).
module engine_sdef
   use core_kinds, only: wp, ip
   use core_motion, only: motion_step_t, motion_step, motion_result_t, stage_args_t
   use core_constants, only: pi
   use core_error, only: error_t, set_error
   use core_output, only: format_real, itoa
   use model_geometry, only: geometry_t
   use model_materials, only: material_table_t
   use model_mechanics, only: mechanics_t
   use model_properties, only: prop_bulk, prop_shear, prop_tf
   implicit none
   private
   public :: sdef_work_t, sdef_prepare, sdef_motion, sdef_timestep, sdef_save, sdef_restore
   public :: sdef_present, sdef_principal, sdef_internal_constants

   !> Per-CYCLE set-up of the SDEF blocks (flat arrays over the list).
   type :: sdef_work_t
      logical :: active = .false.
      integer(ip) :: n = 0
      integer(ip), allocatable :: list(:)       !< block ids
      real(wp), allocatable :: m(:, :)          !< (6, n) generalized mass: m11 m22 m33 m13 m23 (m12 = 0), spare
      real(wp), allocatable :: minv(:, :)       !< (9, n) its inverse, column-major 3x3
      real(wp), allocatable :: d11(:), d12(:), g(:), tf(:)
      integer(ip), allocatable :: cons(:)
      real(wp) :: alpb = 0.0_wp                 !< DAMP INTERNAL mass-proportional [1/s]
      real(wp) :: beta = 0.0_wp                 !< stiffness-proportional [s] (DAMP INTERNAL + global)
      real(wp), allocatable :: saved(:, :)      !< (13, n) state before the step
   end type sdef_work_t

contains

   include 'core_damping.inc'

   !> Does the model hold a live simply-deformable block?
   pure logical function sdef_present(geo)
      type(geometry_t), intent(in) :: geo
      integer(ip) :: b
      sdef_present = .false.
      if (.not. allocated(geo%blocks%sdef)) return
      do b = 1, geo%blocks%n
         if (geo%blocks%live(b) .and. geo%blocks%sdef(b) .and. .not. geo%blocks%fdef(b)) then
            sdef_present = .true.
            return
         end if
      end do
   end function sdef_present

   !> DAMP fcrit freq INTERNAL: mass- and stiffness-proportional constants of
   !> the strain modes (the Rayleigh formulas of the rigid motion, Section 3.6).
   pure subroutine sdef_internal_constants(mech, alpb, betab)
      type(mechanics_t), intent(in) :: mech
      real(wp), intent(out) :: alpb, betab
      real(wp) :: w
      alpb = 0.0_wp
      betab = 0.0_wp
      if (mech%internal_fcrit <= 0.0_wp .or. mech%internal_freq <= 0.0_wp) return
      w = 2.0_wp*pi*mech%internal_freq
      if (mech%internal_mass .and. mech%internal_stiff) then
         alpb = mech%internal_fcrit*w
         betab = mech%internal_fcrit/w
      else if (mech%internal_mass) then
         alpb = 2.0_wp*mech%internal_fcrit*w
      else
         betab = 2.0_wp*mech%internal_fcrit/w
      end if
   end subroutine sdef_internal_constants

   !> Generalized masses (with the inertial block mass of MSCALE: `m_in`),
   !> elastic constants and strengths of every live SDEF block.
   !> `beta_global`: the stiffness-proportional constant of the model's
   !> Rayleigh damping, which acts on the strain modes too.
   subroutine sdef_prepare(geo, mats, mech, m_in, beta_global, work, error)
      type(geometry_t), intent(in) :: geo
      type(material_table_t), intent(in) :: mats
      type(mechanics_t), intent(in) :: mech
      real(wp), intent(in) :: m_in(:), beta_global
      type(sdef_work_t), intent(inout) :: work
      type(error_t), allocatable, intent(out) :: error
      integer(ip) :: b, k, n, c, q, i
      real(wp) :: x1, y1, x2, y2, cr, asum, ixx, iyy, ixy, rho, kb, gb, a(3, 3), inv(3, 3), det
      integer :: mat
      work%active = sdef_present(geo)
      work%n = 0
      if (.not. work%active) return
      n = count(geo%blocks%live(1:geo%blocks%n) .and. geo%blocks%sdef(1:geo%blocks%n) .and. &
                .not. geo%blocks%fdef(1:geo%blocks%n))
      if (allocated(work%list)) deallocate (work%list, work%m, work%minv, work%d11, work%d12, &
                                            work%g, work%tf, work%cons, work%saved)
      allocate (work%list(n), work%m(6, n), work%minv(9, n), work%d11(n), work%d12(n), work%g(n), &
                work%tf(n), work%cons(n), work%saved(13, n))
      call sdef_internal_constants(mech, work%alpb, work%beta)
      work%beta = work%beta + beta_global
      i = 0
      associate (bl => geo%blocks, co => geo%corners)
         do b = 1, bl%n
            if (.not. (bl%live(b) .and. bl%sdef(b) .and. .not. bl%fdef(b))) cycle
            i = i + 1
            work%list(i) = b
            mat = int(bl%material(b))
            kb = mats%get(mat, prop_bulk)
            gb = mats%get(mat, prop_shear)
            if (kb <= 0.0_wp .or. gb <= 0.0_wp) then
               call set_error(error, 'CYCLE: SDEF block '//itoa(b)//' (centroid '// &
                              format_real(bl%xc(b))//', '//format_real(bl%yc(b))// &
                              ') has material '//itoa(int(mat, ip))// &
                              ' without K, G: give PROPERTY MAT='//itoa(int(mat, ip))// &
                              ' K=.. G=..')
               return
            end if
            work%d11(i) = kb + 4.0_wp*gb/3.0_wp
            work%d12(i) = kb - 2.0_wp*gb/3.0_wp
            work%g(i) = gb
            work%cons(i) = bl%cons(b)
            work%tf(i) = mats%get(mat, prop_tf)
            ! second moments about the centroid (clockwise ring: signs)
            ixx = 0.0_wp; iyy = 0.0_wp; ixy = 0.0_wp; asum = 0.0_wp
            c = bl%first_corner(b)
            do k = 1, bl%ncorner(b)
               q = co%next(c)
               x1 = co%x(c) - bl%xc(b); y1 = co%y(c) - bl%yc(b)
               x2 = co%x(q) - bl%xc(b); y2 = co%y(q) - bl%yc(b)
               cr = x1*y2 - x2*y1
               ixx = ixx + cr*(x1*x1 + x1*x2 + x2*x2)
               iyy = iyy + cr*(y1*y1 + y1*y2 + y2*y2)
               ixy = ixy + cr*(x1*y2 + 2.0_wp*x1*y1 + 2.0_wp*x2*y2 + x2*y1)
               asum = asum + cr
               c = q
            end do
            ixx = sign(1.0_wp, asum)*ixx/12.0_wp
            iyy = sign(1.0_wp, asum)*iyy/12.0_wp
            ixy = sign(1.0_wp, asum)*ixy/24.0_wp
            rho = m_in(b)/bl%area(b)
            a = reshape([ixx, 0.0_wp, ixy, 0.0_wp, iyy, ixy, ixy, ixy, ixx + iyy], [3, 3])*rho
            work%m(:, i) = [a(1, 1), a(2, 2), a(3, 3), a(1, 3), a(2, 3), 0.0_wp]
            det = a(1, 1)*(a(2, 2)*a(3, 3) - a(2, 3)*a(3, 2)) - a(1, 2)*(a(2, 1)*a(3, 3) - &
                  a(2, 3)*a(3, 1)) + a(1, 3)*(a(2, 1)*a(3, 2) - a(2, 2)*a(3, 1))
            if (.not. (det > 0.0_wp)) then
               call set_error(error, 'CYCLE: SDEF block '//itoa(b)// &
                              ' has no mass for its strain modes: give PROPERTY DENSITY')
               return
            end if
            inv(1, 1) = a(2, 2)*a(3, 3) - a(2, 3)*a(3, 2)
            inv(1, 2) = a(1, 3)*a(3, 2) - a(1, 2)*a(3, 3)
            inv(1, 3) = a(1, 2)*a(2, 3) - a(1, 3)*a(2, 2)
            inv(2, 1) = a(2, 3)*a(3, 1) - a(2, 1)*a(3, 3)
            inv(2, 2) = a(1, 1)*a(3, 3) - a(1, 3)*a(3, 1)
            inv(2, 3) = a(1, 3)*a(2, 1) - a(1, 1)*a(2, 3)
            inv(3, 1) = a(2, 1)*a(3, 2) - a(2, 2)*a(3, 1)
            inv(3, 2) = a(1, 2)*a(3, 1) - a(1, 1)*a(3, 2)
            inv(3, 3) = a(1, 1)*a(2, 2) - a(1, 2)*a(2, 1)
            work%minv(:, i) = reshape(inv/det, [9])
         end do
      end associate
      work%n = i
   end subroutine sdef_prepare

   !> Largest stable step of the SDEF blocks (before FRACTION; the caller
   !> takes it with FRACTION fz, the rigid modes keep the rigid blocks' bound
   !> under fb): one bound of the whole block, its six modes (translation,
   !> rotation, the three strains) together, with
   !> - K = A [[D11, D12, 0], [D12, D11, 0], [0, 0, 4G]] the internal
   !>   stiffness of the strain modes,
   !> - a spring kj = max(kmax, kmat (l1 + l2)) in x and in y at every corner
   !>   (l1, l2 its edges: the joints a corner and the corners of its
   !>   neighbours on its edges may carry; a contact between corners moves
   !>   with a convex mix of theirs, so this covers it),
   !> - M = diag(m, m, I, M_e), M_e the strain modes' mass (sdef_prepare),
   !> omega_max^2 the largest eigenvalue of M^-1 K (exact, Jacobi rotations
   !> of M^-1/2 K M^-T/2), the step 1 / omega_max: half the critical step
   !> 2 / omega_max of the block between fixed neighbours. Neighbours that
   !> move at most double omega_max^2 (a spring between blocks a, b:
   !> (qa - qb)(qa - qb)^T <= 2 (qa qa^T + qb qb^T)), so the half keeps a
   !> margin of sqrt(2) over the step of the assembled model. Reduced for the
   !> stiffness-proportional internal damping.
   !> Before, the corner contacts took FRACTION fb (0.1) on 2 / sqrt(k m_corner)
   !> and the strain modes fz on a norm bound: an SDEF block stepped at 1/10 -
   !> 1/4 of its critical step, 5 - 7 times below the same block rigid, and
   !> the campaign's SDEF tunnels did not settle (docs/mechanics.md).
   real(wp) function sdef_timestep(geo, work, m_in, i_in, kmat, kmax) result(dt)
      type(geometry_t), intent(in) :: geo
      type(sdef_work_t), intent(in) :: work
      real(wp), intent(in) :: m_in(:), i_in(:), kmat, kmax
      integer(ip) :: i, b, c, k
      real(wp) :: rx, ry, l1, l2, kj, kt(6, 6), t(6, 6), me(3, 3), ll(3, 3), qv(6)
      dt = huge(1.0_wp)
      if (.not. work%active) return
      associate (bl => geo%blocks, co => geo%corners)
         do i = 1, work%n
            b = work%list(i)
            kt = 0.0_wp
            kt(4, 4) = bl%area(b)*work%d11(i); kt(5, 5) = kt(4, 4)
            kt(4, 5) = bl%area(b)*work%d12(i); kt(5, 4) = kt(4, 5)
            kt(6, 6) = bl%area(b)*4.0_wp*work%g(i)
            c = bl%first_corner(b)
            do k = 1, bl%ncorner(b)
               rx = co%x(c) - bl%xc(b)
               ry = co%y(c) - bl%yc(b)
               l1 = hypot(co%x(co%next(c)) - co%x(c), co%y(co%next(c)) - co%y(c))
               l2 = hypot(co%x(co%prev(c)) - co%x(c), co%y(co%prev(c)) - co%y(c))
               kj = max(kmax, kmat*(l1 + l2))
               ! (u, v, theta, exx, eyy, exy): x and y of the corner
               qv = [1.0_wp, 0.0_wp, -ry, rx, 0.0_wp, ry]
               kt = kt + kj*spread(qv, 2, 6)*spread(qv, 1, 6)
               qv = [0.0_wp, 1.0_wp, rx, 0.0_wp, ry, rx]
               kt = kt + kj*spread(qv, 2, 6)*spread(qv, 1, 6)
               c = co%next(c)
            end do
            ! T = M^-1/2: the rigid masses' roots, the inverse Cholesky
            ! factor of the strain modes' mass
            me = reshape([work%m(1, i), 0.0_wp, work%m(4, i), 0.0_wp, work%m(2, i), work%m(5, i), &
                          work%m(4, i), work%m(5, i), work%m(3, i)], [3, 3])
            ll = inverse_cholesky3(me)
            t = 0.0_wp
            t(1, 1) = 1.0_wp/sqrt(m_in(b)); t(2, 2) = t(1, 1)
            t(3, 3) = 1.0_wp/sqrt(i_in(b))
            t(4:6, 4:6) = ll
            if (bl%fixed(b)) t(1:3, 1:3) = 0.0_wp   ! its rigid modes do not move
            kt = matmul(t, matmul(kt, transpose(t)))
            dt = min(dt, damped_step(sqrt(largest_eigenvalue(kt))))
         end do
      end associate
   contains
      !> 2 / omega, halved (see above), reduced for the stiffness-
      !> proportional internal damping (at the critical step 2 / omega).
      pure real(wp) function damped_step(om)
         real(wp), intent(in) :: om
         real(wp) :: h
         if (.not. (om > 0.0_wp)) then
            damped_step = huge(1.0_wp)
         else if (work%beta > 0.0_wp) then
            h = 0.5_wp*work%beta*om
            damped_step = 1.0_wp/om*(sqrt(1.0_wp + h*h) - h)
         else
            damped_step = 1.0_wp/om
         end if
      end function damped_step
   end function sdef_timestep

   !> L^-1 of the Cholesky factor L L^T = a of a symmetric positive definite
   !> 3x3 matrix (lower triangular).
   pure function inverse_cholesky3(a) result(li)
      real(wp), intent(in) :: a(3, 3)
      real(wp) :: li(3, 3), l(3, 3)
      l = 0.0_wp
      l(1, 1) = sqrt(a(1, 1))
      l(2, 1) = a(2, 1)/l(1, 1)
      l(3, 1) = a(3, 1)/l(1, 1)
      l(2, 2) = sqrt(a(2, 2) - l(2, 1)**2)
      l(3, 2) = (a(3, 2) - l(3, 1)*l(2, 1))/l(2, 2)
      l(3, 3) = sqrt(a(3, 3) - l(3, 1)**2 - l(3, 2)**2)
      li = 0.0_wp
      li(1, 1) = 1.0_wp/l(1, 1)
      li(2, 2) = 1.0_wp/l(2, 2)
      li(3, 3) = 1.0_wp/l(3, 3)
      li(2, 1) = -l(2, 1)*li(1, 1)/l(2, 2)
      li(3, 2) = -l(3, 2)*li(2, 2)/l(3, 3)
      li(3, 1) = -(l(3, 1)*li(1, 1) + l(3, 2)*li(2, 1))/l(3, 3)
   end function inverse_cholesky3

   !> Largest eigenvalue of a symmetric 6x6 matrix: cyclic Jacobi rotations
   !> until the off-diagonal part is round-off of the diagonal's.
   pure real(wp) function largest_eigenvalue(a0) result(lmax)
      real(wp), intent(in) :: a0(6, 6)
      real(wp) :: a(6, 6), th, tn, cs, sn, off, dia, col(6)
      integer :: sweep, p, q
      a = 0.5_wp*(a0 + transpose(a0))
      do sweep = 1, 50
         off = 0.0_wp
         dia = 0.0_wp
         do p = 1, 6
            dia = dia + a(p, p)**2
            do q = p + 1, 6
               off = off + a(p, q)**2
            end do
         end do
         if (off <= 1.0e-28_wp*dia) exit
         do p = 1, 5
            do q = p + 1, 6
               if (a(p, q) == 0.0_wp) cycle
               th = (a(q, q) - a(p, p))/(2.0_wp*a(p, q))
               tn = sign(1.0_wp, th)/(abs(th) + sqrt(th*th + 1.0_wp))
               cs = 1.0_wp/sqrt(tn*tn + 1.0_wp)
               sn = tn*cs
               col = a(:, p)
               a(:, p) = cs*col - sn*a(:, q)
               a(:, q) = sn*col + cs*a(:, q)
               col = a(p, :)
               a(p, :) = cs*col - sn*a(q, :)
               a(q, :) = sn*col + cs*a(q, :)
            end do
         end do
      end do
      lmax = maxval([(a(p, p), p=1, 6)])
   end function largest_eigenvalue

   !> Keep the SDEF state before a step (undone with sdef_restore).
   subroutine sdef_save(work, geo)
      type(sdef_work_t), intent(inout) :: work
      type(geometry_t), intent(in) :: geo
      integer(ip) :: i, b
      associate (bl => geo%blocks)
         do i = 1, work%n
            b = work%list(i)
            work%saved(:, i) = [bl%exx(b), bl%eyy(b), bl%exy(b), bl%dxx(b), bl%dyy(b), bl%dxy(b), &
                                bl%sxx(b), bl%syy(b), bl%sxy(b), bl%qxx(b), bl%qyy(b), bl%qxy(b), &
                                real(bl%bstate(b), wp)]
         end do
      end associate
   end subroutine sdef_save

   subroutine sdef_restore(work, geo)
      type(sdef_work_t), intent(in) :: work
      type(geometry_t), intent(inout) :: geo
      if (.not. allocated(work%saved)) return   ! nothing saved
      associate (bl => geo%blocks, b => work%list(1:work%n), n => work%n)
         bl%exx(b) = work%saved(1, 1:n); bl%eyy(b) = work%saved(2, 1:n)
         bl%exy(b) = work%saved(3, 1:n); bl%dxx(b) = work%saved(4, 1:n)
         bl%dyy(b) = work%saved(5, 1:n); bl%dxy(b) = work%saved(6, 1:n)
         bl%sxx(b) = work%saved(7, 1:n); bl%syy(b) = work%saved(8, 1:n)
         bl%sxy(b) = work%saved(9, 1:n); bl%qxx(b) = work%saved(10, 1:n)
         bl%qyy(b) = work%saved(11, 1:n); bl%qxy(b) = work%saved(12, 1:n)
         bl%bstate(b) = nint(work%saved(13, 1:n), ip)
      end associate
   end subroutine sdef_restore

   !> One step of the strain modes of every SDEF block (module header), after
   !> the rigid motion of the step: contact forces (their state of the last
   !> force pass) and the boundary sums (qxx, qyy, qxy, added by the boundary
   !> stage) drive the modes; corners and rounding centres follow the strain
   !> increment. `sa%ms`: the step, with the model's mass-proportional damping
   !> constant alpha and DAMP LOCAL's fraction aloc, -aloc |Q_i| sign(de_i/dt)
   !> on each of the three generalized strain forces Q_i (its power is never
   !> positive). Returns in `sa%res` the kinetic-energy change and damping work of the
   !> strain modes (for DAMP AUTO) and the largest corner travel (no
   !> unbalanced force: the blocks' own is rigid_motion's), and `sa%bad` > 0 the
   !> first block whose strain rate is not finite.
   subroutine sdef_motion(geo, work, sa)
      type(geometry_t), intent(inout) :: geo
      type(sdef_work_t), intent(in) :: work
      type(stage_args_t), intent(inout) :: sa
      type(motion_step_t) :: modes
      integer(ip) :: i, b, c, k, b1, b2
      real(wp) :: fx, fy, px, py, a1, a2, al, dt, q(3), s(3), v0(3), v1(3), de(3)
      real(wp) :: area, dth, cs, sn, rx, ry, dx, dy, k0, k1, t11, t22, t12, vs(3)
      sa%bad = 0
      sa%res = motion_result_t()
      ! the strain modes' step: the model's damping plus DAMP INTERNAL's alpha
      modes = motion_step(sa%ms%grav, sa%ms%dt, sa%ms%alpha + work%alpb, sa%ms%aloc)
      dt = modes%dt
      al = modes%alpha
      a1 = modes%con1
      a2 = modes%con2
      associate (bl => geo%blocks, co => geo%corners, ct => geo%contacts)
         ! contact forces of the last force pass into the applied sums
         do c = 1, ct%n
            if (.not. ct%live(c)) cycle
            b1 = ct%block1(c)
            b2 = ct%block2(c)
            if (.not. (bl%sdef(b1) .or. bl%sdef(b2))) cycle
            fx = ct%state%fn(c)*ct%nx(c) + ct%state%fs(c)*ct%ny(c)
            fy = ct%state%fn(c)*ct%ny(c) - ct%state%fs(c)*ct%nx(c)
            px = ct%x(c)
            py = ct%y(c)
            if (bl%sdef(b2) .and. .not. bl%fdef(b2)) call add_moments(b2, fx, fy)
            if (bl%sdef(b1) .and. .not. bl%fdef(b1)) call add_moments(b1, -fx, -fy)
         end do
         do i = 1, work%n
            b = work%list(i)
            area = bl%area(b)
            ! the rotation of this step turns strain, rate and stress
            dth = bl%vr(b)*dt
            if (dth /= 0.0_wp) then
               cs = cos(dth); sn = sin(dth)
               call turn(bl%exx(b), bl%eyy(b), bl%exy(b))
               call turn(bl%dxx(b), bl%dyy(b), bl%dxy(b))
               call turn(bl%sxx(b), bl%syy(b), bl%sxy(b))
            end if
            v0 = [bl%dxx(b), bl%dyy(b), bl%dxy(b)]
            ! internal stress: elastic plus the stiffness-proportional viscous part
            s = [bl%sxx(b), bl%syy(b), bl%sxy(b)]
            if (work%beta > 0.0_wp) then
               vs(1) = work%d11(i)*v0(1) + work%d12(i)*v0(2)
               vs(2) = work%d12(i)*v0(1) + work%d11(i)*v0(2)
               vs(3) = 2.0_wp*work%g(i)*v0(3)
               s = s + work%beta*vs
            end if
            q(1) = bl%qxx(b) - area*s(1)
            q(2) = bl%qyy(b) - area*s(2)
            q(3) = 2.0_wp*(bl%qxy(b) - area*s(3))
            bl%qxx(b) = 0.0_wp; bl%qyy(b) = 0.0_wp; bl%qxy(b) = 0.0_wp
            q = local_damped(q, v0, modes%aloc)
            ! v1 = (v0 a1 + M^-1 q dt) a2, M^-1 column-major in minv(:, i)
            v1(1) = (v0(1)*a1 + (work%minv(1, i)*q(1) + work%minv(4, i)*q(2) + &
                                 work%minv(7, i)*q(3))*dt)*a2
            v1(2) = (v0(2)*a1 + (work%minv(2, i)*q(1) + work%minv(5, i)*q(2) + &
                                 work%minv(8, i)*q(3))*dt)*a2
            v1(3) = (v0(3)*a1 + (work%minv(3, i)*q(1) + work%minv(6, i)*q(2) + &
                                 work%minv(9, i)*q(3))*dt)*a2
            if (.not. (abs(v1(1)) + abs(v1(2)) + abs(v1(3)) <= huge(1.0_wp))) then
               if (sa%bad == 0) sa%bad = b
               cycle
            end if
            bl%dxx(b) = v1(1); bl%dyy(b) = v1(2); bl%dxy(b) = v1(3)
            k0 = kinetic(i, v0)
            k1 = kinetic(i, v1)
            sa%res%dke = sa%res%dke + abs(k1 - k0)
            sa%res%edamp = sa%res%edamp + al*dt*0.5_wp*kinetic(i, v0 + v1)
            de = v1*dt
            bl%exx(b) = bl%exx(b) + de(1)
            bl%eyy(b) = bl%eyy(b) + de(2)
            bl%exy(b) = bl%exy(b) + de(3)
            bl%sxx(b) = bl%sxx(b) + work%d11(i)*de(1) + work%d12(i)*de(2)
            bl%syy(b) = bl%syy(b) + work%d12(i)*de(1) + work%d11(i)*de(2)
            bl%sxy(b) = bl%sxy(b) + 2.0_wp*work%g(i)*de(3)
            if (work%cons(i) == 4) call griffith(i, b)
            ! corners and rounding centres follow the strain increment
            c = bl%first_corner(b)
            do k = 1, bl%ncorner(b)
               rx = co%x(c) - bl%xc(b)
               ry = co%y(c) - bl%yc(b)
               dx = de(1)*rx + de(3)*ry
               dy = de(3)*rx + de(2)*ry
               co%x(c) = co%x(c) + dx
               co%y(c) = co%y(c) + dy
               co%ux(c) = co%ux(c) + dx
               co%uy(c) = co%uy(c) + dy
               sa%res%travel = max(sa%res%travel, hypot(dx, dy))
               rx = co%rx(c) - bl%xc(b)
               ry = co%ry(c) - bl%yc(b)
               co%rx(c) = co%rx(c) + de(1)*rx + de(3)*ry
               co%ry(c) = co%ry(c) + de(3)*rx + de(2)*ry
               c = co%next(c)
            end do
         end do
      end associate
   contains
      !> 1/2 v' M v of the strain modes of list entry j (M: m11 m22 m33 m13 m23).
      pure real(wp) function kinetic(j, v)
         integer(ip), intent(in) :: j
         real(wp), intent(in) :: v(3)
         kinetic = 0.5_wp*(work%m(1, j)*v(1)*v(1) + work%m(2, j)*v(2)*v(2) + &
                           work%m(3, j)*v(3)*v(3) + 2.0_wp*v(3)*(work%m(4, j)*v(1) + &
                                                               work%m(5, j)*v(2)))
      end function kinetic

      subroutine add_moments(blk, gx, gy)
         integer(ip), intent(in) :: blk
         real(wp), intent(in) :: gx, gy
         real(wp) :: ox, oy
         ox = px - geo%blocks%xc(blk)
         oy = py - geo%blocks%yc(blk)
         geo%blocks%qxx(blk) = geo%blocks%qxx(blk) + gx*ox
         geo%blocks%qyy(blk) = geo%blocks%qyy(blk) + gy*oy
         geo%blocks%qxy(blk) = geo%blocks%qxy(blk) + 0.5_wp*(gx*oy + gy*ox)
      end subroutine add_moments

      !> T <- R T R^T for the rotation (cs, sn) of this step.
      subroutine turn(txx, tyy, txy)
         real(wp), intent(inout) :: txx, tyy, txy
         t11 = cs*cs*txx - 2.0_wp*cs*sn*txy + sn*sn*tyy
         t22 = sn*sn*txx + 2.0_wp*cs*sn*txy + cs*cs*tyy
         t12 = cs*sn*(txx - tyy) + (cs*cs - sn*sn)*txy
         txx = t11; tyy = t22; txy = t12
      end subroutine turn

      !> CONS 4: fracture at the Griffith criterion, then no tension.
      subroutine griffith(j, blk)
         integer(ip), intent(in) :: j, blk
         real(wp) :: sp1, sp2, ang, crit, c2, s2
         associate (bl => geo%blocks)
            call sdef_principal(bl%sxx(blk), bl%syy(blk), bl%sxy(blk), sp1, sp2, ang)
            if (bl%bstate(blk) /= 4) then
               if (3.0_wp*sp1 + sp2 > 0.0_wp) then
                  crit = sp1
               else
                  crit = -(sp1 - sp2)**2/(8.0_wp*(sp1 + sp2))
               end if
               if (crit < work%tf(j)) return
               bl%bstate(blk) = 4
            end if
            if (sp1 <= 0.0_wp) return
            sp1 = 0.0_wp
            sp2 = min(sp2, 0.0_wp)
            c2 = cos(2.0_wp*ang); s2 = sin(2.0_wp*ang)
            bl%sxx(blk) = 0.5_wp*(sp1 + sp2) + 0.5_wp*(sp1 - sp2)*c2
            bl%syy(blk) = 0.5_wp*(sp1 + sp2) - 0.5_wp*(sp1 - sp2)*c2
            bl%sxy(blk) = 0.5_wp*(sp1 - sp2)*s2
         end associate
      end subroutine griffith
   end subroutine sdef_motion

   !> Principal stresses sp1 >= sp2 of (sxx, syy, sxy) and the angle [rad]
   !> of sp1 from the x axis.
   pure subroutine sdef_principal(sxx, syy, sxy, sp1, sp2, ang)
      real(wp), intent(in) :: sxx, syy, sxy
      real(wp), intent(out) :: sp1, sp2, ang
      real(wp) :: c, r
      c = 0.5_wp*(sxx + syy)
      r = hypot(0.5_wp*(sxx - syy), sxy)
      sp1 = c + r
      sp2 = c - r
      ang = 0.5_wp*atan2(2.0_wp*sxy, sxx - syy)
   end subroutine sdef_principal

end module engine_sdef
