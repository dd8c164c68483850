!> The whole problem state. Physics states arrive as allocatable components
!> with the issues that bring them (geometry, mechanics, zones, ...).
module model_state
   implicit none
   private
   public :: model_t, model_reset

   type :: model_t
      character(len=:), allocatable :: heading   !< HEADING title ('' if none)
   end type model_t

contains

   !> A fresh model (START / NEW).
   subroutine model_reset(model)
      type(model_t), intent(out) :: model
      model%heading = ''
   end subroutine model_reset

end module model_state
