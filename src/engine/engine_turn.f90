!> A model held by boundary stresses alone, and its turn as one body.
!>
!> A model that no FIX, prescribed or viscous boundary, free field or
!> boundary-element far field holds has three rigid-body modes. Its net
!> force is the loads' business (engine_cycle's note_net_force names an
!> imbalance). Its turn is not: under boundary stresses that do not turn with
!> the model (a partial tensor per side, such as STRESS 0 0 -10e6 on the top
!> and -5e6 0 0 on the sides, or SET -FUP's fixed forces) a turn by theta
!> brings a moment of about (s1 + s2) L^2 theta that turns it further, an
!> unstable mode growing at sqrt(6 (s1 + s2) / (rho L^2)) for a square of
!> side L (4.6 1/s for 40 m, 15 MPa, 2700 kg/m^3: measured 4.1 1/s on a
!> jointed tunnel model whose SOLVE then never balanced, every block turning
!> at -5.7e-4 rad/s). With the full tensor on every side the mode is neutral
!> (a symmetric stress on a closed boundary has no moment), and adaptive
!> damping, which follows the kinetic energy's changes, does not stop a
!> steady turn either. In the ground the rock around the model holds it.
!>
!> So in such a model under DAMP AUTO (the manual's damping for static
!> problems, Section 4.5) the "turn hold" stage holds the model as one body
!> at the end of each step (turn_hold_step): the net moment of the force
!> sums about the mass centre is balanced by inertia relief, a net force
!> too while it is within the net-force note's tolerance, and a turn the
!> velocities already have, omega = H / J (H the angular momentum, J the
!> polar moment of inertia about the centre, with the inertial masses the
!> motion used: rigid and SDEF blocks with their rotary inertia, gridpoints
!> of FDEF blocks, nodes of structures), is subtracted as the field
!> omega x r. The relative motion is untouched, and a net force above the
!> tolerance (the loads' imbalance) is left to the cycle and its note.
!> Cable and reinforcement nodes are not counted; their grout springs
!> follow the zones they lie in. An extension of the manual, which states
!> no rule; docs/mechanics.md "A model held by stresses alone".
module engine_turn
   use core_kinds, only: wp, ip
   use model_state, only: model_t
   use model_mechanics, only: damping_static
   use model_geometry, only: geometry_t
   use model_boundary, only: bc_velocity, bc_viscous
   use structure_mechanics, only: structure_work_t
   use zones_mechanics, only: zone_work_t
   implicit none
   private
   public :: model_held, turn_hold_wanted, turn_hold_step

contains

   !> Something holds the model in place: a FIXed block, a fixed gridpoint,
   !> a prescribed-velocity, viscous or free-field boundary point, or a
   !> boundary-element far field.
   logical function model_held(model) result(held)
      type(model_t), intent(in) :: model
      integer(ip) :: n, i
      held = .true.
      associate (geo => model%geometry, bnd => model%bound)
         n = geo%gridpoints%n
         if (n > 0) then
            if (any(geo%gridpoints%vfix(1:n) /= 0 .and. geo%gridpoints%live(1:n))) return
         end if
         n = geo%blocks%n
         if (any(geo%blocks%fixed(1:n) .and. geo%blocks%live(1:n))) return
         if (model%be%ne > 0 .or. model%ffield%on) return
         do i = 1, bnd%n
            if (bnd%ix(i) == bc_velocity .or. bnd%iy(i) == bc_velocity .or. &
                bnd%ix(i) == bc_viscous .or. bnd%iy(i) == bc_viscous .or. &
                bnd%vis(i) /= 0 .or. bnd%ff(i) /= 0) return
         end do
      end associate
      held = .false.
   end function model_held

   !> The turn hold runs: DAMP AUTO or LOCAL, boundary conditions given, and nothing
   !> holds the model (model_held).
   logical function turn_hold_wanted(model) result(wanted)
      type(model_t), intent(in) :: model
      wanted = .false.
      if (.not. damping_static(model%mech)) return
      if (model%bound%n == 0) return
      if (model%geometry%blocks%n == 0) return
      wanted = .not. model_held(model)
   end function turn_hold_wanted

   !> Hold the model as one body (module header). At the end of a step,
   !> when the force sums of the next motion are complete:
   !> 1. the net moment about the mass centre of those sums, gravity (real
   !>    mass) and the loads is balanced by the angular acceleration field
   !>    alpha = M / J: each mass gets -m (alpha x r), each rotary inertia
   !>    -I alpha (inertia relief, the device of static analyses of free
   !>    structures);
   !> 2. the net force likewise (-m F / M each), but only when it is within
   !>    `tol` [N]: a larger one is the loads' imbalance, which the CYCLE's
   !>    note names and the model shows;
   !> 3. a turn the velocities already have (omega = H / J) is taken out as
   !>    the field omega x r.
   !> `turn` and `drift` return what the hold took out in this step, as the
   !> angle [rad] and distance [m] it would have moved the model by in dt.
   !> m_in, i_in: the rigid blocks' inertial mass and moment; zw, sw:
   !> the gridpoints' and structure nodes' (their inertial masses; none when
   !> not active).
   subroutine turn_hold_step(model, m_in, i_in, zw, sw, tol, dt, turn, drift)
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: m_in(:), i_in(:)
      type(zone_work_t), intent(in) :: zw
      type(structure_work_t), intent(in) :: sw
      real(wp), intent(in) :: tol, dt
      real(wp), intent(out) :: turn, drift
      real(wp) :: s(10), x0, y0, xc, yc, mt, j, h, mz, fx, fy, ax, ay, alpha, omega, rx, ry, m
      real(wp) :: g(2)
      integer(ip) :: b, k
      logical :: grid, nodes, still
      turn = 0.0_wp
      drift = 0.0_wp
      g = model%gravity
      grid = zw%active .and. allocated(zw%m_in)
      ! gridpoints of excavated (CONS 0) blocks do not move
      still = allocated(zw%still)
      nodes = .false.
      if (allocated(model%structures)) &
         nodes = sw%active .and. allocated(sw%m_in) .and. model%structures%nodes%n > 0
      associate (bl => model%geometry%blocks, gp => model%geometry%gridpoints)
         ! sums about a reference point near the model (no cancellation at
         ! large coordinates): mass, first and second moments, angular
         ! momentum, net force and moment of the force sums, gravity, loads
         x0 = 0.0_wp
         y0 = 0.0_wp
         do b = 1, bl%n
            if (.not. bl%live(b)) cycle
            x0 = bl%xc(b)
            y0 = bl%yc(b)
            exit
         end do
         s = 0.0_wp
         do b = 1, bl%n
            if (.not. bl%live(b) .or. bl%fdef(b)) cycle
            m = m_in(b)
            if (.not. m > 0.0_wp) cycle
            call add(m, i_in(b), bl%xc(b) - x0, bl%yc(b) - y0, bl%vx(b), bl%vy(b), bl%vr(b), &
                     bl%fx(b) + bl%mass(b)*g(1) + bl%lx(b), bl%fy(b) + bl%mass(b)*g(2) + bl%ly(b), &
                     bl%fm(b))
         end do
         if (grid) then
            do k = 1, gp%n
               if (.not. moving(k)) cycle
               ! a gridpoint has no rotational inertia, spin or moment
               call add(zw%m_in(k), 0.0_wp, gp%x(k) - x0, gp%y(k) - y0, gp%vx(k), gp%vy(k), 0.0_wp, &
                        gp%fx(k) + gp%mass(k)*g(1), gp%fy(k) + gp%mass(k)*g(2), 0.0_wp)
            end do
         end if
         if (nodes) then
            associate (nd => model%structures%nodes)
               do k = 1, nd%n
                  call add(sw%m_in(k), sw%i_in(k), nd%x(k) - x0, nd%y(k) - y0, nd%vx(k), &
                           nd%vy(k), nd%vr(k), nd%fx(k) + nd%mass(k)*g(1) + nd%lx(k), &
                           nd%fy(k) + nd%mass(k)*g(2) + nd%ly(k), nd%fm(k))
               end do
            end associate
         end if
         ! s: m, m x, m y, J about the reference, H about it, Fx, Fy, M about
         ! it, momentum Px, Py
         mt = s(1)
         if (.not. mt > 0.0_wp) return
         xc = s(2)/mt
         yc = s(3)/mt
         fx = s(6)
         fy = s(7)
         ! about the mass centre (parallel axes)
         j = s(4) - mt*(xc*xc + yc*yc)
         if (.not. j > 0.0_wp) return
         mz = s(8) - (xc*fy - yc*fx)
         ! angular momentum about the centre: H_ref - c x P
         h = s(5) - (xc*s(10) - yc*s(9))
         alpha = mz/j
         ax = 0.0_wp
         ay = 0.0_wp
         if (hypot(fx, fy) <= tol) then
            ax = fx/mt
            ay = fy/mt
         end if
         omega = h/j
         turn = (abs(omega) + abs(alpha)*dt)*dt
         drift = hypot(ax, ay)*dt*dt
         xc = xc + x0
         yc = yc + y0
         do b = 1, bl%n
            if (.not. bl%live(b) .or. bl%fdef(b)) cycle
            if (.not. m_in(b) > 0.0_wp) cycle
            rx = bl%xc(b) - xc
            ry = bl%yc(b) - yc
            bl%fx(b) = bl%fx(b) - m_in(b)*(ax - alpha*ry)
            bl%fy(b) = bl%fy(b) - m_in(b)*(ay + alpha*rx)
            bl%fm(b) = bl%fm(b) - i_in(b)*alpha
            bl%vx(b) = bl%vx(b) + omega*ry
            bl%vy(b) = bl%vy(b) - omega*rx
            bl%vr(b) = bl%vr(b) - omega
         end do
         if (grid) then
            do k = 1, gp%n
               if (.not. moving(k)) cycle
               rx = gp%x(k) - xc
               ry = gp%y(k) - yc
               gp%fx(k) = gp%fx(k) - zw%m_in(k)*(ax - alpha*ry)
               gp%fy(k) = gp%fy(k) - zw%m_in(k)*(ay + alpha*rx)
               gp%vx(k) = gp%vx(k) + omega*ry
               gp%vy(k) = gp%vy(k) - omega*rx
            end do
         end if
         if (nodes) then
            associate (nd => model%structures%nodes)
               do k = 1, nd%n
                  rx = nd%x(k) - xc
                  ry = nd%y(k) - yc
                  nd%fx(k) = nd%fx(k) - sw%m_in(k)*(ax - alpha*ry)
                  nd%fy(k) = nd%fy(k) - sw%m_in(k)*(ay + alpha*rx)
                  nd%fm(k) = nd%fm(k) - sw%i_in(k)*alpha
                  nd%vx(k) = nd%vx(k) + omega*ry
                  nd%vy(k) = nd%vy(k) - omega*rx
                  nd%vr(k) = nd%vr(k) - omega
               end do
            end associate
         end if
      end associate
   contains
      !> gridpoint k is live and not held still (excavated, CONS 0, blocks)
      logical function moving(k)
         integer(ip), intent(in) :: k
         moving = model%geometry%gridpoints%live(k)
         if (moving .and. still) moving = .not. zw%still(k)
      end function moving

      !> one mass point's share of the sums s (about the reference point)
      subroutine add(m, ri, rx, ry, vx, vy, vr, fx, fy, fm)
         real(wp), intent(in) :: m, ri, rx, ry, vx, vy, vr, fx, fy, fm
         s(1) = s(1) + m
         s(2) = s(2) + m*rx
         s(3) = s(3) + m*ry
         s(4) = s(4) + m*(rx*rx + ry*ry) + ri
         s(5) = s(5) + m*(rx*vy - ry*vx) + ri*vr
         s(6) = s(6) + fx
         s(7) = s(7) + fy
         s(8) = s(8) + rx*fy - ry*fx + fm
         s(9) = s(9) + m*vx
         s(10) = s(10) + m*vy
      end subroutine add

   end subroutine turn_hold_step

end module engine_turn
