!> Commands given in an unusual order or with unusual values (a rock engineer
!> writing decks from the manual's Section 4.5): each case is a defect found
!> by probing; the check fails without its fix. A rejected command must
!> change nothing and its message must name the command and what to do.
program test_command_order
   use core_kinds, only: wp, ip
   use core_error, only: error_t
   use commands_session, only: session_t, session_init
   use testing_session, only: session_run, lines_contain
   use testing, only: check, check_equal, testing_finish
   implicit none

   type(session_t) :: session
   character(len=200), allocatable :: lines(:)

   call test_generate_after_boundary()
   call test_generate_mode_twice()
   call test_damping_zero_frequency()
   call test_mscale_zone_mass_only()
   call test_insitu_before_generate()
   call test_print_no_negative_zero()
   call test_cons4_zoned()
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

   subroutine fresh()
      type(error_t), allocatable :: error
      call session_init(session, error)
      call check(.not. allocated(error), 'session starts')
      call run('ROUND 0.01')
      call run('BLOCK 0,0 0,10 10,10 10,0')
      call run('PROP MAT 1 DENS 2000 BULK 1E9 SHEAR 1E9')
   end subroutine fresh

   !> BOUNDARY STRESS before GENERATE: zoning puts new corners on the edges
   !> (new corner ids), so the forces of the old corners were silently lost
   !> (the zones then carried no stress). GENERATE must refuse and change
   !> nothing; a zoning that adds no boundary point (edmax larger than the
   !> block: 4 zones around the centre) keeps the corners and is accepted.
   subroutine test_generate_after_boundary()
      integer :: nerr
      call fresh()
      call run('BOUND STRESS -1E6 0 -1E6')
      nerr = session%nerrors
      call run('GEN QUAD 5')
      call check_equal(session%nerrors, nerr + 1, 'GEN QUAD after BOUND STRESS: an error')
      call check(printed('GENERATE') .and. printed('BOUNDARY'), &
                 'the message names GENERATE and BOUNDARY')
      call check_equal(int(session%model%geometry%zones%n), 0, 'rejected GENERATE made no zone')
      call check_equal(int(session%model%geometry%blocks%ncorner(1_ip)), 4, &
                       'rejected GENERATE kept the 4 corners')
      call run('GEN EDGE 20')
      call check_equal(session%nerrors, nerr + 1, 'GEN EDGE 20 (no new boundary point) accepted')
      call check_equal(int(session%model%geometry%zones%n), 4, 'GEN EDGE 20: 4 zones')
      ! a boundary list without conditions does not stop GENERATE
      call fresh()
      call run('BOUND XMUL 1')
      nerr = session%nerrors
      call run('GEN QUAD 5')
      call check_equal(session%nerrors, nerr, 'GEN after a BOUNDARY without conditions')
      call check_equal(int(session%model%geometry%zones%n), 16, 'GEN QUAD 5: 16 zones')
   end subroutine test_generate_after_boundary

   !> CHANGE CONS 4 (Griffith fracture, SDEF blocks only) was accepted on
   !> zoned blocks and refused only at CYCLE; now CHANGE refuses it and
   !> changes nothing (not even the rigid blocks in the range). On rigid
   !> blocks alone it is kept with a note (rigid blocks ignore CONS).
   subroutine test_cons4_zoned()
      integer :: nerr
      call fresh()
      call run('CRACK 0,5 10,5')
      call run('GEN 0 10 0 5 AUTO 3')
      nerr = session%nerrors
      call run('CHANGE CONS 4')
      call check_equal(session%nerrors, nerr + 1, 'CHANGE CONS 4 over a zoned block: an error')
      call check(printed('CONS 4') .and. printed('zoned'), 'the message names CONS 4 and the zoned block')
      call check(all(session%model%geometry%blocks%cons(1:2) == 1), 'rejected CHANGE changed no block')
      call run('CHANGE 0 10 5 10 CONS 4')
      call check_equal(session%nerrors, nerr + 1, 'CHANGE CONS 4 on the rigid block accepted')
      call check(printed('SDEF'), 'with a note that CONS 4 is for SDEF blocks')
      ! CONS 2 (a new user's guess at a simply-deformable block): refused,
      ! naming the keyword SDEF
      call run('CHANGE CONS 2')
      call check_equal(session%nerrors, nerr + 2, 'CHANGE CONS 2: an error')
      call check(printed('CHANGE SDEF'), 'the message names CHANGE SDEF')
   end subroutine test_cons4_zoned

   !> GEN EDGE 3 EDGE 4 zoned silently with the first value: a mode keyword
   !> given twice is an error now.
   subroutine test_generate_mode_twice()
      integer :: nerr
      call fresh()
      nerr = session%nerrors
      call run('GEN EDGE 3 EDGE 4')
      call check_equal(session%nerrors, nerr + 1, 'GEN EDGE 3 EDGE 4: an error')
      call check(printed('exactly one'), 'the message says one mode only')
      call check_equal(int(session%model%geometry%zones%n), 0, 'no zone made')
      call run('GEN AUTO 3 EDGE 3')
      call check_equal(session%nerrors, nerr + 2, 'GEN AUTO 3 EDGE 3: an error')
   end subroutine test_generate_mode_twice

   !> DAMP 0.05 0: a fraction of critical damping at frequency 0 switched
   !> damping off silently; now an error that keeps the damping given before.
   !> DAMP 0 0 (fcrit 0) still switches it off.
   subroutine test_damping_zero_frequency()
      integer :: nerr, before
      call fresh()
      call run('DAMP 0.05 10')
      before = session%model%mech%damping
      nerr = session%nerrors
      call run('DAMP 0.05 0')
      call check_equal(session%nerrors, nerr + 1, 'DAMP 0.05 0: an error')
      call check(printed('DAMPING') .and. printed('freq'), 'the message names DAMPING and freq')
      call check_equal(session%model%mech%damping, before, 'rejected DAMP kept the damping')
      call run('DAMP 0 0')
      call check_equal(session%nerrors, nerr + 1, 'DAMP 0 0 accepted (damping off)')
   end subroutine test_damping_zero_frequency

   !> MSCALE ON zcmass without bcmass (the manual: for FDEF blocks bcmass
   !> need not be supplied) was refused by the grammar.
   subroutine test_mscale_zone_mass_only()
      integer :: nerr
      call fresh()
      nerr = session%nerrors
      call run('MSCALE ON 5')
      call check_equal(session%nerrors, nerr, 'MSCALE ON 5 accepted')
      call check(session%model%mech%mscale, 'mass scaling on')
      call check(abs(session%model%mech%mscale_zone - 5.0_wp) == 0.0_wp, 'zone mass 5')
      call check(session%model%mech%mscale_block == 0.0_wp, 'block mass automatic (0)')
   end subroutine test_mscale_zone_mass_only

   !> INSITU before GENERATE set nothing in the zones made later and only said
   !> "0 zone(s)"; on a jointed model the following GENERATE was then refused
   !> with "before the first CYCLE" although no CYCLE had been given. Now
   !> INSITU notes the unzoned blocks and GENERATE's message names INSITU.
   subroutine test_insitu_before_generate()
      integer :: nerr
      call fresh()
      call run('INSITU STRESS -1 0 -1')
      call check(printed('not zoned') .and. printed('GENERATE before INSITU'), &
                 'INSITU on an unzoned block notes it')
      call run('GEN QUAD 5')
      call run('INSITU STRESS -1 0 -1')
      call check(.not. printed('not zoned'), 'no note once the block is zoned')
      call fresh()
      call run('SPLIT 5,-1 5,11')
      call run('PROP MAT 1 JKN 1E10 JKS 1E10')
      call run('INSITU STRESS -1 0 -1')
      nerr = session%nerrors
      call run('GEN QUAD 5')
      call check_equal(session%nerrors, nerr + 1, 'GEN after INSITU on joints: an error')
      call check(printed('INSITU'), 'the message names INSITU')
      call check_equal(int(session%model%geometry%zones%n), 0, 'no zone made')
   end subroutine test_insitu_before_generate

   !> BOUND XMUL -1 XLOAD 5: PRINT BOUNDARY FORCES showed the zero total as
   !> -0.00000E+00 (0 times a negative multiplier).
   subroutine test_print_no_negative_zero()
      call fresh()
      call run('GEN QUAD 5')
      call run('BOUND XMUL -1 XLOAD 5')
      call run('PRINT BOUND FORCES')
      call check(printed('5.00000E+00'), 'the increment is listed')
      call check(.not. printed('-0.00000E+00'), 'no negative zero in PRINT BOUNDARY FORCES')
   end subroutine test_print_no_negative_zero

end program test_command_order
