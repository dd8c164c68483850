!> Restart is exact: the tutorial slope (manual Section 2.1) run for N + M
!> cycles in one session equals N cycles, SAVE, then in a new session
!> RESTART and M cycles, in every field of the model, bit for bit
!> (reference: the uninterrupted run; tolerance: none). A second case
!> restarts in the same session after SAVE / RESTART.
!>
!> Registered as ctest `restart.bit_for_bit` (label restart). The checks
!> that the run really cycled keep it from passing with a CYCLE that does
!> nothing.
program test_restart_bit_for_bit
   use core_kinds, only: wp, i8
   use core_error, only: error_t
   use commands_session, only: session_t, session_init, session_execute_line
   use io_posix, only: posix_unlink
   use testing, only: check, check_equal, testing_finish
   use testing_model, only: compare_models
   implicit none

   integer, parameter :: n_first = 100, n_second = 150
   character(len=*), parameter :: file = 'restart_bit_for_bit.sav'
   type(session_t) :: straight, before, after, same_session
   character(len=16) :: first, second

   write (first, '(i0)') n_first
   write (second, '(i0)') n_second

   ! N + M without a stop
   call new_session(straight)
   call run(straight, 'CYCLE '//trim(first))
   call run(straight, 'CYCLE '//trim(second))

   ! N, SAVE; then a fresh session: RESTART, M
   call new_session(before)
   call run(before, 'CYCLE '//trim(first))
   call run(before, 'SAVE '//file)
   call new_session(after)
   call run(after, 'RESTART '//file)
   call run(after, 'CYCLE '//trim(second))

   ! N, SAVE, RESTART, M in one session
   call new_session(same_session)
   call run(same_session, 'CYCLE '//trim(first))
   call run(same_session, 'SAVE '//file)
   call run(same_session, 'RESTART '//file)
   call run(same_session, 'CYCLE '//trim(second))

   ! the runs did cycle (a CYCLE that does nothing would make this vacuous)
   call check(straight%model%mech%step == int(n_first + n_second, i8), &
              'the straight run executed N + M cycles')
   call check(any(straight%model%geometry%blocks%vy(1:straight%model%geometry%blocks%n) &
                  /= 0.0_wp), 'the blocks move')
   call check(straight%model%hist%nsample > 0, 'history samples were taken')
   call check(any(straight%model%geometry%contacts%state%fn( &
                  1:straight%model%geometry%contacts%n) /= 0.0_wp), 'contacts carry force')
   call check_equal(straight%nerrors + before%nerrors + after%nerrors + same_session%nerrors, &
                    0, 'no command was rejected')

   call compare_models(straight%model, after%model, 'restart in a new session')
   call compare_models(straight%model, same_session%model, 'restart in the same session')
   if (posix_unlink(file)) continue
   call testing_finish()

contains

   !> A session holding the tutorial slope model, output silenced.
   subroutine new_session(s)
      type(session_t), intent(out) :: s
      type(error_t), allocatable :: error
      call session_init(s, error)
      call check(.not. allocated(error), 'session starts')
      s%out%screen = .false.
      call run(s, 'BLOCK (0,0) (0,20) (20,20) (20,0)')
      call run(s, 'SPLIT (0,2) (20,8)')
      call run(s, 'SPLIT (5,3) (5,20)')
      call run(s, 'SPLIT (5,12) (20,18)')
      call run(s, 'FIX 0,20 0,5')
      call run(s, 'FIX 0,5 0,20')
      call run(s, 'PROP MAT=1 DENS=2000')
      call run(s, 'PROP JMAT=1 JKN=1.33E7 JKS=1.33E7 JFRIC=0.35')
      call run(s, 'GRAVITY 0 -10')
      call run(s, 'DAMP AUTO')
      call run(s, 'HIST YVEL(10,20) TYPE 1')
   end subroutine new_session

   subroutine run(s, line)
      type(session_t), intent(inout) :: s
      character(len=*), intent(in) :: line
      call session_execute_line(s, line, 0)
   end subroutine run

end program test_restart_bit_for_bit
