!> Recoverable errors as values (fpm style): a routine that can fail takes
!> `type(error_t), allocatable, intent(out) :: error` and allocates it on failure.
module core_error
   implicit none
   private
   public :: error_t, set_error

   !> A failed operation: a one-line message naming what was wrong.
   type :: error_t
      character(len=:), allocatable :: message
      !> a numerical failure of the calculation (CYCLE undid its last step),
      !> not an error in the input
      logical :: numerical = .false.
   end type error_t

contains

   !> Allocate `error` with `message` (`numerical`: a failure of the
   !> calculation, not of the input).
   subroutine set_error(error, message, numerical)
      type(error_t), allocatable, intent(inout) :: error
      character(len=*), intent(in) :: message
      logical, intent(in), optional :: numerical
      if (allocated(error)) deallocate (error)
      allocate (error)
      error%message = message
      if (present(numerical)) error%numerical = numerical
   end subroutine set_error

end module core_error
