!> Fluid commands (commands_fluid): a rejected FLUID, PFIX, PFREE or
!> BOUNDARY PP / IMPERMEABLE line changes nothing - in particular it does not
!> create the model's fluid part (a model without one runs no fluid code).
!>
!> Model: two rigid blocks (0..2) x (0..1) split by a crack at y = 0.5, so
!> the joint holds inner domains between its contacts.
program test_fluid_commands
   use core_kinds, only: wp
   use core_error, only: error_t
   use model_fluid, only: bnd_open, bnd_pressure
   use commands_session, only: session_t, session_init
   use testing_session, only: session_run, lines_contain
   use testing, only: check, check_equal, testing_finish
   implicit none

   type(session_t) :: session
   character(len=200), allocatable :: lines(:)

   call test_rejected_lines_create_nothing()
   call test_rejected_lines_change_nothing()
   call testing_finish()

contains

   subroutine run(text)
      character(len=*), intent(in) :: text
      call session_run(session, text, lines)
   end subroutine run

   logical function printed(text)
      character(len=*), intent(in) :: text
      printed = lines_contain(lines, text)
   end function printed

   subroutine two_blocks()
      type(error_t), allocatable :: error
      call session_init(session, error)
      call check(.not. allocated(error), 'session_init')
      call run('ROUND 0.01')
      call run('BLOCK 0,0 0,1 2,1 2,0')
      call run('CRACK 0,0.5 2,0.5')
      call run('PROP MAT=1 D=1 JKN=100 JKS=100 JPERM=1e8 AZERO=1e-4 ARES=1e-4')
   end subroutine two_blocks

   !> Each rejected line: one more error, a message naming the command, and
   !> still no fluid part.
   subroutine rejected(text, word, what)
      character(len=*), intent(in) :: text, word, what
      integer :: nerr
      nerr = session%nerrors
      call run(text)
      call check(session%nerrors == nerr + 1, what//': an error')
      call check(printed(word), what//': the message names '//word)
      call check(.not. allocated(session%model%fluid), what//': no fluid part created')
   end subroutine rejected

   subroutine test_rejected_lines_create_nothing()
      call two_blocks()
      call rejected('PFIX DOMAIN 999 PRESSURE 1', 'PFIX DOMAIN 999', 'PFIX unknown domain')
      call rejected('PFIX DOMAIN 0 PRESSURE 1', 'PFIX DOMAIN', 'PFIX domain 0')
      call rejected('PFIX XGRAD', 'PFIX', 'PFIX without PRESSURE value')
      call rejected('PFIX 0 1 0 1 DOMAIN 1 PRESSURE 1', 'PFIX', 'PFIX range and DOMAIN')
      call rejected('PFREE 999', 'PFREE 999', 'PFREE unknown domain')
      call rejected('BOUNDARY CORNER 1 2 PP 1', 'BOUNDARY CORNER', 'BOUNDARY CORNER PP')
      call rejected('BOUNDARY PP 1 IMPERMEABLE', 'IMPERMEABLE', 'BOUNDARY PP with IMPERMEABLE')
      ! the fluid part of the line is fine, the mechanical part fails (a
      ! user-supplied history function; XVEL on rigid corners, the failure
      ! used here before issue 22, is accepted now)
      call rejected('BOUNDARY -1 3 -1 2 PP 1 XLOAD 1 XHISTORY FUNCTION', 'FUNCTION', &
                    'BOUNDARY PP with a bad history')
      call rejected('FLUID -1 100', "FLUID", 'FLUID negative density')
      call rejected('FLUID 1 100 -0.1', '-0.1', 'FLUID negative yield strength')
      ! and the accepted forms do create it
      call run('BOUNDARY -1 3 -1 2 PP 1')
      call check(allocated(session%model%fluid), 'BOUNDARY PP creates the fluid part')
   end subroutine test_rejected_lines_create_nothing

   subroutine test_rejected_lines_change_nothing()
      integer :: nerr, nfix
      call two_blocks()
      call run('FLUID 1 100 0.5')
      call check(allocated(session%model%fluid), 'FLUID creates the fluid part')
      call check(session%model%fluid%cohw == 0.5_wp, 'FLUID: COHW kept')
      call check(printed('Bingham'), 'FLUID COHW > 0: says the fluid is a Bingham fluid')
      call run('PFIX PRESSURE 2')
      nfix = count(session%model%fluid%fixed(1:session%model%fluid%nd))
      call check(nfix > 0, 'PFIX without range fixes the inner domains')
      nerr = session%nerrors
      call run('PFREE 999')
      call check(session%nerrors == nerr + 1, 'PFREE 999 rejected')
      call check_equal(count(session%model%fluid%fixed(1:session%model%fluid%nd)), nfix, &
                       'rejected PFREE frees nothing')
      call run('BOUNDARY -1 3 -1 2 PP 5 XLOAD 1 XHISTORY FUNCTION')
      call check(session%nerrors == nerr + 2, 'BOUNDARY PP ... XHISTORY FUNCTION rejected')
      call check(all(session%model%fluid%bnd_code(1:session%model%fluid%nc) == bnd_open), &
                 'rejected BOUNDARY sets no fluid boundary')
      call run('FLUID 2 -5')
      call check(session%nerrors == nerr + 3, 'FLUID negative bulk modulus rejected')
      call check(session%model%fluid%rhow == 1.0_wp .and. session%model%fluid%bulkw == 100.0_wp, &
                 'rejected FLUID keeps density and bulk modulus')
      call run('BOUNDARY -1 3 -1 2 PP 5')
      call check(session%nerrors == nerr + 3, 'BOUNDARY PP accepted')
      call check(any(session%model%fluid%bnd_code(1:session%model%fluid%nc) == bnd_pressure), &
                 'BOUNDARY PP sets reservoir contacts')
   end subroutine test_rejected_lines_change_nothing

end program test_fluid_commands
