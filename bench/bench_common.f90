!> Helpers shared by the benchmarks (bench/*_bench.f90): the median of the
!> repeats and running one command line in a session.
module bench_common
   use core_kinds, only: wp
   use commands_session, only: session_t, session_execute_line
   implicit none
   private
   public :: median, exec

contains

   !> One command line in session `s`.
   subroutine exec(s, line)
      type(session_t), intent(inout) :: s
      character(len=*), intent(in) :: line
      call session_execute_line(s, line, 1)
   end subroutine exec

   !> Median of x (mean of the two middle values for an even count).
   real(wp) function median(x)
      real(wp), intent(in) :: x(:)
      real(wp) :: y(size(x)), t
      integer :: i, j
      y = x
      do i = 2, size(y)
         t = y(i)
         j = i - 1
         do while (j >= 1)
            if (y(j) <= t) exit
            y(j + 1) = y(j)
            j = j - 1
         end do
         y(j + 1) = t
      end do
      if (mod(size(y), 2) == 1) then
         median = y(size(y)/2 + 1)
      else
         median = 0.5_wp*(y(size(y)/2) + y(size(y)/2 + 1))
      end if
   end function median

end module bench_common
