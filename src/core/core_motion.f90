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
module core_motion
   use core_kinds, only: wp
   implicit none
   private
   public :: motion_step_t, motion_step

   type :: motion_step_t
      real(wp) :: grav(2) = 0.0_wp   !< gravitational acceleration (x, y)
      real(wp) :: dt = 0.0_wp        !< the time step
      real(wp) :: alpha = 0.0_wp     !< mass-proportional damping constant [1/s]
      real(wp) :: aloc = 0.0_wp      !< DAMP LOCAL's fraction of |F| (0 under other damping)
      real(wp) :: con1 = 1.0_wp      !< Eq. 28's CON1 = 1 - alpha dt / 2
      real(wp) :: con2 = 1.0_wp      !< Eq. 28's CON2 = 1 / (1 + alpha dt / 2)
   end type motion_step_t

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

end module core_motion
