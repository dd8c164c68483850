!> Boundary conditions during a CYCLE (manual Section 4.5 BOUNDARY; the
!> engine calls these three kernels):
!>
!>   boundary_cycle_start  before the first step: records the start time of
!>                         the CYCLE (SINE / COSINE run from it) and sets the
!>                         prescribed velocities of the first step;
!>   boundary_step         once per step k = 1..ncycles, after the contact and
!>                         zone forces of the step are summed: applied force
!>                         xmul (fx + dfx h(t)) into the gridpoint (FDEF corner)
!>                         or into the block's force and moment about its
!>                         centroid (rigid corner); prescribed velocities
!>                         xmul vx h(t) into gridpoints with the vfix bit (no
!>                         force is added in a velocity direction, so the
!>                         gridpoint force sum stays the reaction; a load
!>                         stored there is kept in fx, dfx and PRINT BOUNDARY
!>                         FORCES adds it to the reaction);
!>   boundary_cycle_end    increments into the totals, history types back to
!>                         CONSTANT (a history is in effect for one CYCLE);
!>                         the same for the SET ZPRESS sources
!>                         (zones_pressure's zpress_cycle_end).
!>
!> h(t) is model_boundary's boundary_history_value for the point's history
!> type in that direction. Dead corners and corners of dead blocks are skipped.
!>
!> Boundary stresses kept as tractions (SET FUP, model_boundary): each step
!> adds to fx / dfx the force of the stored stress on the point's two half
!> edges with the edges' CURRENT geometry, 0.5 sigma . (L n), where L n is
!> (-dy, dx) for the clockwise edge from the point to the next corner and
!> (dy, -dx) ... to the previous one (d = other end - this point): a follower
!> load that turns and stretches with the boundary. For a constant symmetric
!> sigma on a closed boundary the forces add up to zero force and zero moment
!> in any position, so a model held by its in-situ stress has no rigid-body
!> mode driven by its loads (verification/E/README.md; docs/zones.md). At a
!> joint mouth the segment to the neighbouring block's corner (`end_prev`,
!> `end_next`) is loaded too: without it the opening and shear of the joints
!> that reach the boundary leave gaps in the loop whose missing tractions are
!> a net moment (a 10 m model at 10 MPa with 0.1 mm joint displacements: of
!> order 1e4 N m) that turns the whole model.
!> `boundary_freeze_tractions` (SET -FUP) turns them into fixed forces.
module zones_boundary
   use core_forces, only: add_rigid_force, add_sdef_moments
   use core_kinds, only: wp, ip, i8
   use core_motion, only: stage_args_t
   use model_geometry, only: geometry_t
   use model_zones, only: vfix_x, vfix_y
   use model_boundary, only: boundary_t, boundary_history_value, boundary_has_traction, &
                             boundary_clear_tractions, bc_velocity, bh_constant
   use zones_pressure, only: zpress_cycle_end
   implicit none
   private
   public :: boundary_cycle_start, boundary_step, boundary_cycle_end, boundary_acts
   public :: boundary_traction_force, boundary_freeze_tractions, boundary_freeze_point

contains

   !> Before the first step (sa%k = 0) of a CYCLE of sa%ncycles steps at
   !> problem time sa%time.
   subroutine boundary_cycle_start(bnd, geo, sa)
      type(boundary_t), intent(inout) :: bnd
      type(geometry_t), intent(inout) :: geo
      type(stage_args_t), intent(in) :: sa
      bnd%t_start = sa%time
      call set_velocities(bnd, geo, sa)
   end subroutine boundary_cycle_start

   !> Whether boundary_step has anything to do in this model: false when every
   !> live point is on a corner of a rigid or SDEF block (no gridpoint), has
   !> no viscous or free-field condition, no history, and in each direction
   !> either a velocity (held by the stage block velocities) or no load and no
   !> traction. Rollers and FIXed velocities under a rigid model are such
   !> points: the stage boundaries is then left out of the step (a scene pays
   !> only for the effects it calls for).
   logical function boundary_acts(bnd, geo) result(acts)
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(in) :: geo
      integer(ip) :: i, c
      acts = .true.
      associate (co => geo%corners, bl => geo%blocks)
         do i = 1, bnd%n
            c = bnd%corner(i)
            if (c < 1 .or. c > co%n) return
            if (.not. co%live(c)) cycle
            if (.not. bl%live(co%block(c))) cycle
            if (co%gp(c) /= 0 .or. bnd%vis(i) /= 0 .or. bnd%ff(i) /= 0) return
            if (bnd%hx(i) /= bh_constant .or. bnd%hy(i) /= bh_constant) return
            if (boundary_has_traction(bnd, i)) return
            if (bnd%ix(i) /= bc_velocity .and. (bnd%fx(i) /= 0.0_wp .or. bnd%dfx(i) /= 0.0_wp)) &
               return
            if (bnd%iy(i) /= bc_velocity .and. (bnd%fy(i) /= 0.0_wp .or. bnd%dfy(i) /= 0.0_wp)) &
               return
         end do
      end associate
      acts = .false.
   end function boundary_acts

   !> Step sa%k (1..sa%ncycles) at problem time sa%time. fxhis, fyhis: the value of
   !> the x / y history of the first boundary point (in list order) whose
   !> condition in that direction has a history other than CONSTANT, 1 when
   !> none has (the manual's FXHIS, FYHIS; HISTORY XHIS / YHIS).
   subroutine boundary_step(bnd, geo, sa, fxhis, fyhis)
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(inout) :: geo
      type(stage_args_t), intent(in) :: sa
      real(wp), intent(out) :: fxhis, fyhis
      integer(ip) :: i, c, b, g
      real(wp) :: hx, hy, fx, fy, tfx, tfy, tdfx, tdfy
      logical :: seen_x, seen_y
      fxhis = 1.0_wp
      fyhis = 1.0_wp
      seen_x = .false.
      seen_y = .false.
      associate (co => geo%corners, bl => geo%blocks, gp => geo%gridpoints)
         do i = 1, bnd%n
            c = bnd%corner(i)
            if (.not. co%live(c)) cycle
            b = co%block(c)
            if (.not. bl%live(b)) cycle
            call direction_factor(bnd%hx(i), bnd%freqx(i), bnd%tloadx(i), hx, fxhis, seen_x)
            call direction_factor(bnd%hy(i), bnd%freqy(i), bnd%tloady(i), hy, fyhis, seen_y)
            call boundary_traction_force(bnd, geo, i, tfx, tfy, tdfx, tdfy)
            fx = bnd%xmul(i)*(bnd%fx(i) + tfx + (bnd%dfx(i) + tdfx)*hx)
            fy = bnd%ymul(i)*(bnd%fy(i) + tfy + (bnd%dfy(i) + tdfy)*hy)
            g = co%gp(c)
            if (g > 0) then
               if (bnd%ix(i) == bc_velocity) then
                  gp%vx(g) = bnd%xmul(i)*bnd%vx(i)*hx
               else
                  gp%fx(g) = gp%fx(g) + fx
               end if
               if (bnd%iy(i) == bc_velocity) then
                  gp%vy(g) = bnd%ymul(i)*bnd%vy(i)*hy
               else
                  gp%fy(g) = gp%fy(g) + fy
               end if
            else
               ! a velocity on a rigid or SDEF block's corner holds that
               ! direction (stage block velocities, engine_rigid_velocity): the
               ! load stored under it waits, as at a gridpoint
               if (bnd%ix(i) == bc_velocity) fx = 0.0_wp
               if (bnd%iy(i) == bc_velocity) fy = 0.0_wp
               call add_rigid_force(bl%fx, bl%fy, bl%fm, b, co%x(c) - bl%xc(b), &
                                    co%y(c) - bl%yc(b), fx, fy)
               ! a simply-deformable block: the first moments drive its strain
               ! modes (engine_sdef)
               if (bl%sdef(b)) call add_sdef_moments(bl%qxx, bl%qyy, bl%qxy, b, &
                                                     co%x(c) - bl%xc(b), co%y(c) - bl%yc(b), fx, fy)
            end if
         end do
      end associate
   contains
      !> History factor h of one direction of a point (1 for CONSTANT); the
      !> first point with a history in that direction gives `his`.
      subroutine direction_factor(hcode, freq, tload, h, his, seen)
         integer, intent(in) :: hcode
         real(wp), intent(in) :: freq, tload
         real(wp), intent(out) :: h
         real(wp), intent(inout) :: his
         logical, intent(inout) :: seen
         h = 1.0_wp
         if (hcode == bh_constant) return
         h = boundary_history_value(bnd, hcode, freq, tload, sa%time, sa%k, sa%ncycles)
         if (.not. seen) his = h
         seen = .true.
      end subroutine direction_factor
   end subroutine boundary_step

   !> After the last step of a CYCLE: the Note under BOUNDARY. With the
   !> problem time, the steps taken (k) and the CYCLE's count: a prescribed
   !> velocity, load or stress increment that followed a history (LINEAR,
   !> SINE, COSINE, table) keeps the value it had at the end of the CYCLE,
   !> h(t_end) times it, from then on (docs/zones.md: a SINE over whole
   !> periods or past its tload leaves the boundary at rest and unloaded, a
   !> LINEAR ramp holds its value). A stress increment whose XHIS and YHIS
   !> end at different values is kept as the point's forces (`geo`: the
   !> edges at the end). Without them only the folding.
   subroutine boundary_cycle_end(bnd, time, k, ncycles, geo)
      type(boundary_t), intent(inout) :: bnd
      real(wp), intent(in), optional :: time
      integer(i8), intent(in), optional :: k, ncycles
      type(geometry_t), intent(in), optional :: geo
      integer(ip) :: n, i
      real(wp) :: hvx, hvy, tfx, tfy, tdfx, tdfy
      call zpress_cycle_end(bnd%zp)
      n = bnd%n
      if (n == 0) return
      if (present(time) .and. present(k) .and. present(ncycles)) then
         if (k > 0) then
            do i = 1, n
               if (bnd%hx(i) == bh_constant .and. bnd%hy(i) == bh_constant) cycle
               hvx = 1.0_wp
               hvy = 1.0_wp
               if (bnd%hx(i) /= bh_constant) hvx = boundary_history_value(bnd, bnd%hx(i), &
                                                     bnd%freqx(i), bnd%tloadx(i), time, k, ncycles)
               if (bnd%hy(i) /= bh_constant) hvy = boundary_history_value(bnd, bnd%hy(i), &
                                                     bnd%freqy(i), bnd%tloady(i), time, k, ncycles)
               if (bnd%ix(i) == bc_velocity) bnd%vx(i) = bnd%vx(i)*hvx
               if (bnd%iy(i) == bc_velocity) bnd%vy(i) = bnd%vy(i)*hvy
               ! a load or stress keeps the value its history reached, as a
               ! velocity does: a SINE pulse over whole periods or past its
               ! tload, or a table past its last value, leaves no static
               ! load (the Note read literally left the full increment)
               bnd%dfx(i) = bnd%dfx(i)*hvx
               bnd%dfy(i) = bnd%dfy(i)*hvy
               if (hvx == hvy) then
                  call scale_stress_increment(i, hvx)
               else if (present(geo)) then
                  ! XHIS and YHIS differ: the shear stress drove x with one
                  ! and y with the other (by the edge's direction), so the
                  ! increment's end value is kept as the point's forces
                  call boundary_traction_force(bnd, geo, i, tfx, tfy, tdfx, tdfy)
                  bnd%dfx(i) = bnd%dfx(i) + hvx*tdfx
                  bnd%dfy(i) = bnd%dfy(i) + hvy*tdfy
                  call scale_stress_increment(i, 0.0_wp)
               end if
            end do
         end if
      end if
      bnd%fx(1:n) = bnd%fx(1:n) + bnd%dfx(1:n)
      bnd%fy(1:n) = bnd%fy(1:n) + bnd%dfy(1:n)
      bnd%dfx(1:n) = 0.0_wp
      bnd%dfy(1:n) = 0.0_wp
      bnd%sxx_prev(1:n) = bnd%sxx_prev(1:n) + bnd%dsxx_prev(1:n)
      bnd%sxy_prev(1:n) = bnd%sxy_prev(1:n) + bnd%dsxy_prev(1:n)
      bnd%syy_prev(1:n) = bnd%syy_prev(1:n) + bnd%dsyy_prev(1:n)
      bnd%sxx_next(1:n) = bnd%sxx_next(1:n) + bnd%dsxx_next(1:n)
      bnd%sxy_next(1:n) = bnd%sxy_next(1:n) + bnd%dsxy_next(1:n)
      bnd%syy_next(1:n) = bnd%syy_next(1:n) + bnd%dsyy_next(1:n)
      call clear_traction_increments(bnd)
      bnd%hx(1:n) = bh_constant
      bnd%hy(1:n) = bh_constant
      bnd%freqx(1:n) = 0.0_wp
      bnd%tloadx(1:n) = 0.0_wp
      bnd%freqy(1:n) = 0.0_wp
      bnd%tloady(1:n) = 0.0_wp
   contains
      subroutine scale_stress_increment(j, f)
         integer(ip), intent(in) :: j
         real(wp), intent(in) :: f
         bnd%dsxx_prev(j) = f*bnd%dsxx_prev(j)
         bnd%dsxx_next(j) = f*bnd%dsxx_next(j)
         bnd%dsyy_prev(j) = f*bnd%dsyy_prev(j)
         bnd%dsyy_next(j) = f*bnd%dsyy_next(j)
         bnd%dsxy_prev(j) = f*bnd%dsxy_prev(j)
         bnd%dsxy_next(j) = f*bnd%dsxy_next(j)
      end subroutine scale_stress_increment
   end subroutine boundary_cycle_end

   !> Force of the tractions of point i on its current half edges (module
   !> header): (fx, fy) from the totals, (dfx, dfy) from the increments of
   !> the next CYCLE. Zero for a point without tractions.
   pure subroutine boundary_traction_force(bnd, geo, i, fx, fy, dfx, dfy)
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: i
      real(wp), intent(out) :: fx, fy, dfx, dfy
      integer(ip) :: c, o
      real(wp) :: lnx_next, lny_next, lnx_prev, lny_prev
      c = bnd%corner(i)
      ! half of L n of each edge: (-dy, dx) / 2 to the next corner, (dy, -dx) / 2
      ! to the previous one (d = other end - c; blocks are clockwise)
      ! a gap segment whose far block was deleted since carries nothing
      o = geo%corners%next(c)
      if (bnd%end_next(i) > 0) o = bnd%end_next(i)
      if (.not. alive(o)) o = c
      lnx_next = -0.5_wp*(geo%corners%y(o) - geo%corners%y(c))
      lny_next = 0.5_wp*(geo%corners%x(o) - geo%corners%x(c))
      o = geo%corners%prev(c)
      if (bnd%end_prev(i) > 0) o = bnd%end_prev(i)
      if (.not. alive(o)) o = c
      lnx_prev = 0.5_wp*(geo%corners%y(o) - geo%corners%y(c))
      lny_prev = -0.5_wp*(geo%corners%x(o) - geo%corners%x(c))
      fx = bnd%sxx_next(i)*lnx_next + bnd%sxy_next(i)*lny_next + &
           bnd%sxx_prev(i)*lnx_prev + bnd%sxy_prev(i)*lny_prev
      fy = bnd%sxy_next(i)*lnx_next + bnd%syy_next(i)*lny_next + &
           bnd%sxy_prev(i)*lnx_prev + bnd%syy_prev(i)*lny_prev
      dfx = bnd%dsxx_next(i)*lnx_next + bnd%dsxy_next(i)*lny_next + &
            bnd%dsxx_prev(i)*lnx_prev + bnd%dsxy_prev(i)*lny_prev
      dfy = bnd%dsxy_next(i)*lnx_next + bnd%dsyy_next(i)*lny_next + &
            bnd%dsxy_prev(i)*lnx_prev + bnd%dsyy_prev(i)*lny_prev
   contains
      pure logical function alive(k)
         integer(ip), intent(in) :: k
         alive = geo%corners%live(k)
         if (alive) alive = geo%blocks%live(geo%corners%block(k))
      end function alive
   end subroutine boundary_traction_force

   !> SET -FUP: the tractions of every point become fixed forces (totals into
   !> fx / fy, increments into dfx / dfy) with the boundary's present
   !> geometry; `nfrozen` points had tractions.
   subroutine boundary_freeze_tractions(bnd, geo, nfrozen)
      type(boundary_t), intent(inout) :: bnd
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(out) :: nfrozen
      integer(ip) :: i
      nfrozen = 0
      do i = 1, bnd%n
         if (.not. boundary_has_traction(bnd, i)) cycle
         nfrozen = nfrozen + 1
         call boundary_freeze_point(bnd, geo, i)
      end do
   end subroutine boundary_freeze_tractions

   !> The tractions of point i become fixed forces (as boundary_freeze_tractions).
   subroutine boundary_freeze_point(bnd, geo, i)
      type(boundary_t), intent(inout) :: bnd
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: i
      real(wp) :: fx, fy, dfx, dfy
      if (.not. boundary_has_traction(bnd, i)) return
      call boundary_traction_force(bnd, geo, i, fx, fy, dfx, dfy)
      bnd%fx(i) = bnd%fx(i) + fx
      bnd%fy(i) = bnd%fy(i) + fy
      bnd%dfx(i) = bnd%dfx(i) + dfx
      bnd%dfy(i) = bnd%dfy(i) + dfy
      call boundary_clear_tractions(bnd, i)
   end subroutine boundary_freeze_point

   subroutine clear_traction_increments(bnd)
      type(boundary_t), intent(inout) :: bnd
      integer(ip) :: n
      n = bnd%n
      bnd%dsxx_prev(1:n) = 0.0_wp
      bnd%dsxy_prev(1:n) = 0.0_wp
      bnd%dsyy_prev(1:n) = 0.0_wp
      bnd%dsxx_next(1:n) = 0.0_wp
      bnd%dsxy_next(1:n) = 0.0_wp
      bnd%dsyy_next(1:n) = 0.0_wp
   end subroutine clear_traction_increments

   !> Prescribed velocities at step sa%k (0: before the first step).
   subroutine set_velocities(bnd, geo, sa)
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(inout) :: geo
      type(stage_args_t), intent(in) :: sa
      integer(ip) :: i, c, g
      real(wp) :: h
      associate (co => geo%corners, gp => geo%gridpoints)
         do i = 1, bnd%n
            c = bnd%corner(i)
            if (.not. co%live(c)) cycle
            g = co%gp(c)
            if (g <= 0) cycle
            if (bnd%ix(i) == bc_velocity) then
               h = boundary_history_value(bnd, bnd%hx(i), bnd%freqx(i), bnd%tloadx(i), &
                                          sa%time, sa%k, sa%ncycles)
               gp%vx(g) = bnd%xmul(i)*bnd%vx(i)*h; gp%vfix(g) = ior(gp%vfix(g), vfix_x)
            end if
            if (bnd%iy(i) == bc_velocity) then
               h = boundary_history_value(bnd, bnd%hy(i), bnd%freqy(i), bnd%tloady(i), &
                                          sa%time, sa%k, sa%ncycles)
               gp%vy(g) = bnd%ymul(i)*bnd%vy(i)*h; gp%vfix(g) = ior(gp%vfix(g), vfix_y)
            end if
         end do
      end associate
   end subroutine set_velocities

end module zones_boundary
