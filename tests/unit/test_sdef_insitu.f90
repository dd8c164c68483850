!> INSITU on simply-deformable blocks (UDEC manual (ICG1.5, 1989), Section
!> 4.5 INSITU: "initial stresses"; an SDEF block carries one uniform stress,
!> Section 3.2): the block's stress is the field at its centroid (the block
!> mean of a linear field). Checks, exact up to round-off (1e-12 relative):
!> * INSITU STRESS -1e6 0 -2e6 YGRAD 0 0 1e4 on a unit SDEF block centred at
!>   (0.5, 2.5): sxx = -1e6, syy = -2e6 + 1e4 x 2.5;
!> * the block with BOUNDARY STRESS equal to that uniform state on all its
!>   edges is in equilibrium: 200 cycles leave its strains below 1e-12 (before
!>   the fix INSITU left the SDEF stress 0 and the boundary stress strained
!>   the block by about 6e-4).
program test_sdef_insitu
   use core_kinds, only: wp
   use core_error, only: error_t
   use commands_session, only: session_t, session_init
   use testing_session, only: session_run, lines_contain
   use testing, only: check, check_close, testing_finish
   implicit none

   type(session_t) :: session
   character(len=200), allocatable :: lines(:)
   type(error_t), allocatable :: error

   call session_init(session, error)
   call check(.not. allocated(error), 'session starts')
   call run('ROUND 0.001')
   call run('BLOCK 0,2 0,3 1,3 1,2')
   call run('CHANGE SDEF')
   call run('PROP MAT 1 D 2000 K 1E9 G 6E8')
   call run('INSITU STRESS -1e6 0 -2e6 YGRAD 0 0 1e4')
   call check(lines_contain(lines, '1 SDEF block(s)'), 'INSITU counts the SDEF block')
   associate (bl => session%model%geometry%blocks)
      call check_close(bl%sxx(1), -1.0e6_wp, 1.0e-12_wp, 'INSITU: SDEF sxx')
      call check_close(bl%syy(1), -2.0e6_wp + 2.5e4_wp, 1.0e-12_wp, 'INSITU: SDEF syy at the centroid')
      call check(bl%sxy(1) == 0.0_wp, 'INSITU: SDEF sxy')
   end associate
   call run('INSITU STRESS -1e6 0 -1e6')
   call run('BOUND STRESS -1e6 0 -1e6')
   call run('CYCLE 200')
   associate (bl => session%model%geometry%blocks)
      call check(max(abs(bl%exx(1)), abs(bl%eyy(1)), abs(bl%exy(1))) < 1.0e-12_wp, &
                 'INSITU + the same boundary stress: the SDEF block stays unstrained')
   end associate
   call testing_finish()

contains

   subroutine run(text)
      character(len=*), intent(in) :: text
      call session_run(session, text, lines)
   end subroutine run

end program test_sdef_insitu
