!> Recoverable errors as values (fpm style): a routine that can fail takes
!> `type(error_t), allocatable, intent(out) :: error` and allocates it on failure.
module core_error
   implicit none
   private
   public :: error_t, set_error

   !> A failed operation: a one-line message naming what was wrong.
   type :: error_t
      character(len=:), allocatable :: message
   end type error_t

contains

   !> Allocate `error` with `message`.
   subroutine set_error(error, message)
      type(error_t), allocatable, intent(inout) :: error
      character(len=*), intent(in) :: message
      if (allocated(error)) deallocate (error)
      allocate (error)
      error%message = message
   end subroutine set_error

end module core_error
