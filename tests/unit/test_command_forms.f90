!> The command language as a new user types it (manual Section 4.1 and the
!> commands of Section 4.5), and the debts found walking it:
!>  - PROPERTY: a block keyword after JMAT n (`PROP JMAT=1 FRIC=30`) is
!>    refused naming the keyword and the joint keywords meant, and changes
!>    nothing; joint keywords after MAT n stay accepted (the manual's decks
!>    give them so, Appendix decks `PROP M=1 D=... JKN=...`).
!>  - number and separator forms: commas, `=`, signs, exponents.
!>  - Ctrl-C / SIGTERM reaching GENERATE, JSET, PLOT or SAVE stops the
!>    command and leaves the model (and an older save file) as before it.
!>  - SET PTOL is a pressure (Section 3.12): the same flow deck in MPa and in
!>    Pa gives the same pressures with PTOL 0.01 MPa and 1e4 Pa; a PTOL far
!>    below the pressures is noted by CYCLE.
program test_command_forms
   use, intrinsic :: iso_c_binding, only: c_int
   use core_kinds, only: wp, ip
   use core_error, only: error_t
   use core_interrupt, only: interrupt_install, interrupt_clear, interrupt_pending, &
                             signal_terminate
   use commands_session, only: session_t, session_init
   use testing_session, only: session_run, lines_contain
   use testing, only: check, check_equal, testing_finish
   implicit none

   interface
      integer(c_int) function c_raise(sig) bind(c, name='raise')
         import :: c_int
         integer(c_int), value :: sig
      end function c_raise
   end interface

   type(session_t) :: session
   character(len=200), allocatable :: lines(:)

   call test_property_kinds()
   call test_number_forms()
   call test_interrupted_commands()
   call test_ptol_is_a_pressure()
   call testing_finish()

contains

   subroutine fresh()
      type(error_t), allocatable :: error
      call session_init(session, error)
      call check(.not. allocated(error), 'session_init')
   end subroutine fresh

   !> The lines PRINT PROPERTY prints now.
   function properties() result(text)
      character(len=200), allocatable :: text(:)
      call session_run(session, 'PRINT PROPERTY', lines)
      text = lines
   end function properties

   !> `line` is refused: one more error, the message holds each of `words`,
   !> and PRINT PROPERTY prints what it printed before.
   subroutine refused_property(line, words)
      character(len=*), intent(in) :: line
      character(len=*), intent(in) :: words(:)
      character(len=200), allocatable :: before(:), after(:)
      integer :: nerr, k
      before = properties()
      nerr = session%nerrors
      call session_run(session, line, lines)
      call check(session%nerrors == nerr + 1, line//': refused')
      do k = 1, size(words)
         call check(lines_contain(lines, trim(words(k))), line//': the message names '//trim(words(k)))
      end do
      after = properties()
      call check(size(after) == size(before), line//': PRINT PROPERTY unchanged (lines)')
      if (size(after) == size(before)) &
         call check(all(after == before), line//': PRINT PROPERTY unchanged')
   end subroutine refused_property

   subroutine accepted(line)
      character(len=*), intent(in) :: line
      integer :: nerr
      nerr = session%nerrors
      call session_run(session, line, lines)
      call check(session%nerrors == nerr, line//': accepted')
   end subroutine accepted

   real(wp) function prop(mat, name)
      integer, intent(in) :: mat
      character(len=*), intent(in) :: name
      integer :: k, mat_read
      character(len=16) :: cname
      prop = -1.0_wp
      call session_run(session, 'PRINT PROPERTY', lines)
      do k = 1, size(lines)
         read (lines(k), *, err=1, end=1) mat_read, cname
         if (mat_read /= mat .or. trim(cname) /= name) cycle
         read (lines(k), *) mat_read, cname, prop
         return
1        continue
      end do
   end function prop

   subroutine test_property_kinds()
      call fresh()
      call accepted('PROP MAT=1 D=2000 FRIC=0.5 COH=1e6')
      ! a block keyword after JMAT n (Section 4.5: joint materials take the
      ! JCONS 1 and JCONS 2, 3, 5 keywords only)
      call refused_property('PROP JMAT=1 FRIC=30', [character(len=12) :: 'FRICTION', 'JMAT', &
                            'JFRIC', 'CFRIC'])
      call refused_property('prop jmat 1 jkn 1e9 d 5', [character(len=12) :: 'DENSITY', 'JMAT'])
      call refused_property('PROP JM=2 K=1e9', [character(len=12) :: 'K', 'JKN'])
      call refused_property('PROP JMAT=1 COND=3', [character(len=12) :: 'COND', 'JMAT'])
      ! a later MAT / JMAT on the line switches the kind
      call refused_property('PROP MAT=1 D=1 JMAT=2 JKN=1 T=5', [character(len=12) :: 'TENSILE'])
      ! the manual's forms stay accepted
      call accepted('PROP JMAT=1 KN=5000 JKN=10000 JKS=10000 JCOH=2.5 JTENS=1E6')
      call accepted('PROP M=1 D=2850 K=61.8E9 G=35.3E9 JKN=531.9E9 JKS=438.8E9 JF=1.0724')
      call accepted('PROP MAT=1 JMAT=2 JF=0.3 MAT=3 D=5')
      call check(abs(prop(1, 'JFRIC') - 1.0724_wp) < 1.0e-12_wp, 'MAT 1 JF stored')
      call check(abs(prop(2, 'JFRIC') - 0.3_wp) < 1.0e-12_wp, 'JMAT 2 JF stored')
      call check(abs(prop(1, 'FRICTION') - 0.5_wp) < 1.0e-12_wp, 'MAT 1 FRIC kept')
   end subroutine test_property_kinds

   !> Section 4.1: blanks or any of ( ) , / = separate; a real may omit its
   !> decimal point; an integer must not have one.
   subroutine test_number_forms()
      character(len=40), parameter :: forms(8) = [character(len=40) :: &
         'GRAVITY 0 -9.81', 'grav 0,-9.81', 'GR 0 , -9.81', 'gravity = 0 -981E-2', &
         'GRAV +0 -.981E1', 'grav (0, -9.81)', 'grav 0/-9.81', 'Grav 0.0e0 -9.810']
      integer :: k
      call fresh()
      do k = 1, size(forms)
         session%model%gravity = 0.0_wp
         call accepted(trim(forms(k)))
         call check(session%model%gravity(1) == 0.0_wp .and. &
                    abs(session%model%gravity(2) + 9.81_wp) < 1.0e-12_wp, &
                    trim(forms(k))//': gravity (0, -9.81)')
      end do
      call accepted('grav 0 -1.E1')
      call check(session%model%gravity(2) == -10.0_wp, 'grav 0 -1.E1: -10')
      ! refused and nothing changed: a missing value, an extra value, a word
      call refused_gravity('grav 0', 'GRAVITY')
      call refused_gravity('grav 0 -9.81 5', '5')
      call refused_gravity('grav 0 abc', 'abc')
      ! DAMP AUTO with a Rayleigh keyword: refused, the damping as before
      call accepted('DAMP 0.05 10 MASS')
      call session_run(session, 'DAMP AUTO 0.5 MASS', lines)
      call check(lines_contain(lines, 'DAMPING AUTO: STIFFNESS, MASS and INTERNAL'), &
                 'DAMP AUTO 0.5 MASS: refused, naming the Rayleigh keywords')
      call session_run(session, 'PRINT STATUS', lines)
      call check(lines_contain(lines, 'Rayleigh'), 'DAMP AUTO 0.5 MASS: the damping as before')
      call fresh()
      call accepted('ROUND 0.01')
      call accepted('BLOCK 0,0 0,1 2,1 2,0')
      call refused_property('PROP MAT=1 DENS', [character(len=12) :: 'DENSITY'])
      call refused_property('PROP MAT=1 DENS=-5', [character(len=12) :: 'DENSITY', '-5'])
      call refused_property('PROP MAT=1.5 DENS=3', [character(len=12) :: 'MATERIAL', '1.5'])
      call refused_property('PROP DENS=3 MAT=1', [character(len=12) :: 'MAT n'])
      call refused_property('PROP MAT=1 DENS=1e6 2', [character(len=12) :: '2'])
      call accepted('prop mat = 1 , dens = 2.E3')
      call check(prop(1, 'DENSITY') == 2000.0_wp, 'prop mat = 1 , dens = 2.E3: 2000')
      call test_range_after_keywords()
   end subroutine test_number_forms

   !> Section 4.5 PRINT: "the range must be first on the input line"; a user
   !> writes it after the keywords. PRINT ZONE STRESS 0 5 0 5 was read as
   !> PRINT STRESS's grid (xl xu yl yu nx ny) short of nx ny; it is the zone
   !> table in the range, as PRINT 0 5 0 5 ZONE STRESS.
   subroutine test_range_after_keywords()
      character(len=200), allocatable :: first(:)
      call fresh()
      call accepted('ROUND 0.05')
      call accepted('BLOCK 0,0 0,10 10,10 10,0')
      call accepted('CHANGE CONS 1')
      call accepted('GEN AUTO 5')
      call accepted('PRINT 0 5 0 5 ZONE STRESS')
      first = lines
      call check(size(first) > 2 .and. size(first) < 20, 'PRINT 0 5 0 5 ZONE STRESS: some zones')
      call accepted('print zone stress 0 5 0 5')
      call check(size(lines) == size(first), 'PRINT ZONE STRESS 0 5 0 5: the same zones')
      if (size(lines) == size(first)) call check(all(lines == first), &
                                                 'PRINT ZONE STRESS 0 5 0 5: the same table')
      ! the grid form keeps its own message when nx ny are missing
      call session_run(session, 'PRINT STRESS 0 10 0 10', lines)
      call check(lines_contain(lines, 'PRINT STRESS: expected xl xu yl yu nx ny'), &
                 'PRINT STRESS 0 10 0 10: names the missing grid')
      call accepted('PRINT STRESS 0 10 0 10 2 2')
   end subroutine test_range_after_keywords

   subroutine refused_gravity(line, word)
      character(len=*), intent(in) :: line, word
      integer :: nerr
      session%model%gravity = [1.0_wp, 2.0_wp]
      nerr = session%nerrors
      call session_run(session, line, lines)
      call check(session%nerrors == nerr + 1, line//': refused')
      call check(lines_contain(lines, word), line//': the message names '//word)
      call check(all(session%model%gravity == [1.0_wp, 2.0_wp]), line//': gravity unchanged')
   end subroutine refused_gravity

   !> SIGTERM pending when the command starts (as if it had arrived at its
   !> first poll): the command stops, says so, is not counted as an input
   !> error, and the model is as before it.
   subroutine test_interrupted_commands()
      integer :: nerr, u, ios
      integer(ip) :: nblocks, ncorners, nzones
      call fresh()
      call interrupt_install(.false.)
      call accepted('ROUND 0.02')
      call accepted('BLOCK 0,0 0,4 4,4 4,0')
      call accepted('JSET 30 0 100 0 0 0 0.5 0 0 0')
      call accepted('CHANGE CONS 1')
      call accepted('PROP MAT=1 D=2000 K=1e9 G=1e9 JKN=1e9 JKS=1e9')
      nblocks = count(session%model%geometry%blocks%live(1:session%model%geometry%blocks%n))
      ncorners = session%model%geometry%corners%n

      ! JSET: the blocks and the random sequence as before
      nerr = session%nerrors
      call raise_sigterm()
      call session_run(session, 'JSET -60 0 100 0 0 0 0.3 0 0 0', lines)
      call check(lines_contain(lines, 'JSET interrupted'), 'JSET: says it was interrupted')
      call check(session%nerrors == nerr, 'JSET interrupted: not an input error')
      call check(count(session%model%geometry%blocks%live(1:session%model%geometry%blocks%n)) &
                 == nblocks, 'JSET interrupted: the blocks as before')
      call check(session%model%geometry%corners%n == ncorners, 'JSET interrupted: corners as before')
      call interrupt_clear()

      ! GENERATE: nothing zoned
      call raise_sigterm()
      call session_run(session, 'GEN AUTO 0.2', lines)
      call check(lines_contain(lines, 'GENERATE interrupted'), 'GENERATE: says it was interrupted')
      call check(session%nerrors == nerr, 'GENERATE interrupted: not an input error')
      call check(session%model%geometry%zones%n == 0, 'GENERATE interrupted: no zone')
      call check(all(session%model%geometry%blocks%nzone(1:session%model%geometry%blocks%n) == 0), &
                 'GENERATE interrupted: no block zoned')
      call interrupt_clear()
      call accepted('GEN AUTO 0.2')
      nzones = session%model%geometry%zones%n
      call check(nzones > 0, 'GENERATE after the interrupt zones the blocks')

      ! PLOT: no picture
      call raise_sigterm()
      call session_run(session, 'PLOT BLOCK ZONE', lines)
      call check(lines_contain(lines, 'PLOT interrupted'), 'PLOT: says it was interrupted')
      call check(session%nerrors == nerr, 'PLOT interrupted: not an input error')
      call interrupt_clear()

      ! SAVE: the older file is kept, no temporary is left
      call accepted('GRAVITY 0 -9.81')
      call accepted('SAVE test_command_forms.sav')
      call accepted('GRAVITY 0 -1')
      call raise_sigterm()
      call session_run(session, 'SAVE test_command_forms.sav', lines)
      call check(lines_contain(lines, 'interrupted'), 'SAVE: says it was interrupted')
      call check(session%nerrors == nerr, 'SAVE interrupted: not an input error')
      call interrupt_clear()
      call accepted('RESTART test_command_forms.sav')
      call check(session%model%gravity(2) == -9.81_wp, 'SAVE interrupted: the older file is kept')
      call check(session%model%geometry%zones%n == nzones, 'RESTART of the older file: its zones')
      open (newunit=u, file='test_command_forms.sav', status='old', iostat=ios)
      if (ios == 0) close (u, status='delete')
      call execute_command_line('ls test_command_forms.sav?* > /dev/null 2>&1', exitstat=ios)
      call check(ios /= 0, 'SAVE interrupted: no temporary file left')
      call check(.not. interrupt_pending(), 'no interrupt left pending')
   end subroutine test_interrupted_commands

   subroutine raise_sigterm()
      integer(c_int) :: rc
      rc = c_raise(int(signal_terminate, c_int))
      call check(rc == 0 .and. interrupt_pending(), 'SIGTERM raised and pending')
   end subroutine raise_sigterm

   !> Section 4.5 SET PTOL: "domain pressure variable tolerance for fluid flow
   !> calculation (default is 0.01)", the pressure increment that triggers the
   !> mechanical update of the steady-flow logic (Section 3.12: "whenever the
   !> maximum increment of pressure in any domain exceeds some prescribed
   !> tolerance"): a pressure in the deck's stress unit. The same deck in MPa
   !> and in Pa (every stress, modulus, stiffness and density times 1e6, the
   !> permeability factor over 1e6) with PTOL 0.01 and 1e4 triggers alike:
   !> the pressures agree to rounding (1e-9 of the largest). The Pa deck with
   !> the default PTOL is told that it triggers at every sweep; the MPa deck
   !> (PTOL 1 % of its pressures) is not.
   subroutine test_ptol_is_a_pressure()
      real(wp), allocatable :: p_mpa(:), p_pa(:)
      real(wp) :: scale
      call flow_deck(1.0e6_wp, '', p_mpa)
      call check(.not. lines_contain(lines, 'SET PTOL'), 'MPa deck, default PTOL: no note')
      call flow_deck(1.0_wp, 'SET PTOL 1e4', p_pa)
      call check(.not. lines_contain(lines, 'SET PTOL'), 'Pa deck, PTOL 1e4: no note')
      call check(size(p_mpa) == size(p_pa) .and. size(p_pa) > 4, 'flow decks: same domains')
      if (size(p_mpa) /= size(p_pa)) return
      scale = maxval(abs(p_pa))
      call check(scale > 1.0e3_wp, 'flow deck (Pa): pressures have risen')
      call check(maxval(abs(p_pa - p_mpa)) <= 1.0e-9_wp*scale, &
                 'PTOL 0.01 MPa and 1e4 Pa: the same pressures')
      call flow_deck(1.0_wp, '', p_pa)
      call check(lines_contain(lines, 'SET PTOL 0.01,') .and. lines_contain(lines, 'try SET PTOL 1000'), &
                 'Pa deck, default PTOL: CYCLE notes it and suggests 1 % of the pressures')
      call session_run(session, 'CYCLE 1', lines)
      call check(.not. lines_contain(lines, 'SET PTOL'), 'the note is given once')
      call accepted('SET PTOL 0.001')
      call session_run(session, 'CYCLE 1', lines)
      call check(lines_contain(lines, 'SET PTOL 0.001,'), 'a new PTOL is weighed again')
   end subroutine test_ptol_is_a_pressure

   !> Rigid jointed square, blocks held, water from a reservoir at the top;
   !> `s`: the deck's stress unit in Pa (1: Pa, 1e6: MPa), `extra` a line
   !> given before the CYCLE; `p` the domain pressures in Pa after 5 cycles
   !> (the CYCLE's output in `lines`).
   subroutine flow_deck(s, extra, p)
      real(wp), intent(in) :: s
      character(len=*), intent(in) :: extra
      real(wp), allocatable, intent(out) :: p(:)
      character(len=200) :: line
      call fresh()
      call accepted('ROUND 0.01')
      call accepted('BLOCK 0,0 0,2 4,2 4,0')
      call accepted('JSET 0 0 10 0 0 0 0.5 0 0 0.25')
      call accepted('JSET 90 0 10 0 0 0 1 0 0.5 0')
      write (line, '(a,4(es12.5,a))') 'PROP MAT=1 D=', 2650.0_wp/s, ' JKN=', 1.0e10_wp/s, &
         ' JKS=', 1.0e10_wp/s, ' JPERM=', 83.33_wp*s, ' AZERO=1e-4 ARES=5e-5'
      call accepted(trim(line))
      call accepted('FIX -1 5 -1 3')
      write (line, '(a,2(es12.5,a))') 'FLUID ', 1000.0_wp/s, ' ', 2.0e9_wp/s, ''
      call accepted(trim(line))
      call accepted('SET SFLOW')
      ! small sweeps (fw 0.05): several of them between mechanical updates
      call accepted('FRACTION 0.1 1.0 0.05')
      write (line, '(a,es12.5)') 'BOUND -1 5 1.9 2.1 PP ', 1.0e5_wp/s
      call accepted(trim(line))
      if (len(extra) > 0) call accepted(extra)
      call accepted('CYCLE 5')
      p = session%model%fluid%p(1:session%model%fluid%nd)*s
   end subroutine flow_deck

end program test_command_forms
