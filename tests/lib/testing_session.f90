!> Running command lines in a test session and reading what they printed
!> (shared by the unit tests that drive the command interpreter).
module testing_session
   use commands_session, only: session_t, session_execute_line
   implicit none
   private
   public :: session_run, lines_contain

contains

   !> Run one command line in `session` (screen output off); `lines`
   !> receives every line it printed, in order.
   subroutine session_run(session, text, lines)
      type(session_t), intent(inout) :: session
      character(len=*), intent(in) :: text
      character(len=200), allocatable, intent(inout) :: lines(:)
      integer :: capture, ios, n
      character(len=200) :: line
      character(len=200), allocatable :: grown(:)
      open (newunit=capture, status='scratch', action='readwrite')
      session%out%screen = .false.
      call session%out%add_unit(capture)
      call session_execute_line(session, text, 1)
      call session%out%remove_unit(capture)
      rewind (capture)
      if (allocated(lines)) deallocate (lines)
      allocate (lines(16))
      n = 0
      do
         read (capture, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (n == size(lines)) then
            allocate (grown(2*n))
            grown(1:n) = lines(1:n)
            call move_alloc(grown, lines)
         end if
         n = n + 1
         lines(n) = line
      end do
      close (capture)
      lines = lines(1:n)
   end subroutine session_run

   !> Some line of `lines` contains `text`.
   pure logical function lines_contain(lines, text) result(found)
      character(len=*), intent(in) :: lines(:), text
      integer :: i
      found = .false.
      do i = 1, size(lines)
         if (index(lines(i), text) > 0) found = .true.
      end do
   end function lines_contain

end module testing_session
