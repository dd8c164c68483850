!> The plot settings of a session (window, default route, last picture):
!> they belong to the session, not the model (commands_plot).
module commands_plot_state
   use core_kinds, only: wp
   use plot_scene, only: plot_scene_t
   implicit none
   private
   public :: plot_state_t

   type :: plot_state_t
      logical :: window_auto = .true.
      real(wp) :: window(4) = [0.0_wp, 1.0_wp, 0.0_wp, 1.0_wp]
      character(len=:), allocatable :: route      !< device of the default route
      character(len=:), allocatable :: output     !< SET OUTPUT file ('' : PLT)
      logical :: has_scene = .false.
      logical :: copied = .true.                  !< the scene has been written
      type(plot_scene_t) :: scene
   end type plot_state_t

end module commands_plot_state
