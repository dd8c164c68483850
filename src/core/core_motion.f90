!> What one explicit motion step needs besides the entities it moves: the
!> bundle the cycle hands to every motion routine (rigid blocks, their
!> prescribed velocities, SDEF strain modes, gridpoints, structural nodes,
!> cable nodes, the free-field columns) instead of the same long argument list.
!>
!> The damped central-difference step of UDEC manual (ICG1.5, 1989), Section
!> 3.6, Eq. 28: v(t + dt/2) = (v(t - dt/2) CON1 + F dt / m) CON2, with
!> CON1 = 1 - alpha dt / 2 and CON2 = 1 / (1 + alpha dt / 2) for the
!> mass-proportional damping constant alpha; DAMP LOCAL (an extension,
!> docs/mechanics.md) takes aloc |F| sign(v) off each force. The factors are
!> computed here once per step (`motion_step`), as every routine wrote them.
!>
!> What a motion routine returns is one bundle too (`motion_result_t`): the
!> largest unbalanced force and where it is, the kinetic-energy change and
!> damping work DAMP AUTO compares (Section 3.6), and the largest travel of a
!> point that decides when contacts are searched again; `motion_add` folds a
!> stage's bundle into the step's.
module core_motion
   use core_kinds, only: wp, ip, i8
   implicit none
   private
   public :: motion_step_t, motion_step, motion_result_t, motion_add, stage_args_t

   type :: motion_step_t
      real(wp) :: grav(2) = 0.0_wp   !< gravitational acceleration (x, y)
      real(wp) :: dt = 0.0_wp        !< the time step
      real(wp) :: alpha = 0.0_wp     !< mass-proportional damping constant [1/s]
      real(wp) :: aloc = 0.0_wp      !< DAMP LOCAL's fraction of |F| (0 under other damping)
      real(wp) :: con1 = 1.0_wp      !< Eq. 28's CON1 = 1 - alpha dt / 2
      real(wp) :: con2 = 1.0_wp      !< Eq. 28's CON2 = 1 / (1 + alpha dt / 2)
      !> sum the Rayleigh quotient's terms of the step's motion (kvv, mvv of
      !> motion_result_t): DAMP AUTO after a load change on a zoned model
      logical :: probe = .false.
   end type motion_step_t

   !> The results of one motion stage (or, folded by motion_add, of the step).
   type :: motion_result_t
      real(wp) :: unbal = 0.0_wp     !< largest unbalanced force of a free entity
      integer(ip) :: at = 0          !< that entity of the stage (0: none)
      real(wp) :: dke = 0.0_wp       !< sum of |kinetic-energy change| (DAMP AUTO)
      real(wp) :: edamp = 0.0_wp     !< energy taken by damping (DAMP AUTO)
      real(wp) :: travel = 0.0_wp    !< largest travel of a point
      !> with motion_step_t%probe: -dF . v, the change of the force sums over
      !> the last step against the velocity that made it (dF = -K v dt, so
      !> this is dt v.K v), and m v.v of the same velocity (gridpoints only)
      real(wp) :: kvv = 0.0_wp
      real(wp) :: mvv = 0.0_wp
   end type motion_result_t

   !> What the cycle hands a stage of the step (engine_cycle's run_stage; the
   !> stages of engine_stages): the step as it stands when the stage runs
   !> (ms), the time at the end of the step, the step's number within the
   !> CYCLE and the CYCLE's length (boundary and free-field histories), what
   !> a motion stage hands back (res) and where its state stopped being
   !> finite (bad). One argument instead of the five
   !> to eight each stage routine would otherwise restate.
   type :: stage_args_t
      type(motion_step_t) :: ms = motion_step_t()
      real(wp) :: time = 0.0_wp      !< the time at the end of this step
      integer(i8) :: k = 0           !< this step within the CYCLE (0: before the first)
      integer(i8) :: ncycles = 0     !< the CYCLE's steps
      type(motion_result_t) :: res = motion_result_t()
      !> the stage's first entity whose state is not finite (0: none), in the
      !> stage's own numbering, for a stage that judges its state itself
      integer(ip) :: bad = 0
   end type stage_args_t

contains

   !> The bundle of a step of length dt under gravity grav with damping
   !> constant alpha and DAMP LOCAL fraction aloc.
   pure function motion_step(grav, dt, alpha, aloc) result(ms)
      real(wp), intent(in) :: grav(2), dt, alpha, aloc
      type(motion_step_t) :: ms
      ms%grav = grav
      ms%dt = dt
      ms%alpha = alpha
      ms%aloc = aloc
      ms%con1 = 1.0_wp - 0.5_wp*alpha*dt
      ms%con2 = 1.0_wp/(1.0_wp + 0.5_wp*alpha*dt)
   end function motion_step

   !> Fold a stage's results into the step's: the energies add, the largest
   !> unbalanced force and travel are kept. The entity `at` stays the step's
   !> (the rigid stage's block): the stages number different entities. The
   !> caller judges a non-finite part%unbal first (it names the entity).
   pure subroutine motion_add(total, part)
      type(motion_result_t), intent(inout) :: total
      type(motion_result_t), intent(in) :: part
      total%unbal = max(total%unbal, part%unbal)
      total%dke = total%dke + part%dke
      total%edamp = total%edamp + part%edamp
      total%kvv = total%kvv + part%kvv
      total%mvv = total%mvv + part%mvv
      total%travel = max(total%travel, part%travel)
   end subroutine motion_add

end module core_motion
