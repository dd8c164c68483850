!> Heat conduction (commands_thermal, thermal_conduction, engine_thermal):
!> error paths, the 1-D steady closed form with a fixed face and convection,
!> explicit and implicit agreement, RUN + SAVE + RESTART + RUN against one
!> RUN, and the thermal stresses of TFIX (Eq. 7-3).
!> References are hand formulas stated next to each check.
program test_thermal
   use core_kinds, only: wp, ip
   use core_error, only: error_t
   use commands_session, only: session_t, session_init
   use testing_session, only: session_run, lines_contain
   use testing, only: check, check_close, testing_finish
   implicit none

   type(session_t) :: session
   character(len=200), allocatable :: lines(:)

   call test_errors()
   call test_steady_wall()
   call test_restart_continues()
   call test_thermal_stress()
   call test_thermal_history()
   call test_run_timed()
   call test_issue22_slips()
   call test_table_tadd()
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
      call run('ROUND 0.001')
   end subroutine fresh

   !> A 1 x 0.2 strip, zoned, k = 2, rho Cp = 1; x = 0 held at 100, convection
   !> h = 4 to 0 degrees on x = 1.
   subroutine wall()
      call fresh()
      call run('THERMAL')
      call run('BLOCK 0,0 0,0.2 1,0.2 1,0')
      call run('GEN -1 2 -1 1 AUTO 0.1')
      call run('PROP MAT 1 DENS 1 SPEC 1 COND 2')
      call run('TFIX 100 -0.01 0.01 -1 1')
      call run('THAPP 0.99 1.01 -1 1 CONV 4 0')
   end subroutine wall

   !> Largest |T - expected(x)| over the gridpoints, expected linear in x.
   real(wp) function wall_error() result(err)
      integer(ip) :: g
      real(wp) :: q, expected
      ! series resistances 1/k + 1/h = 0.5 + 0.25: q = 100 / 0.75,
      ! T(x) = 100 - q x / k
      q = 100.0_wp/0.75_wp
      err = 0.0_wp
      associate (gp => session%model%geometry%gridpoints, th => session%model%thermal)
         do g = 1, gp%n
            expected = 100.0_wp - q*gp%x(g)/2.0_wp
            err = max(err, abs(th%temp(g) - expected))
         end do
      end associate
   end function wall_error

   subroutine test_errors()
      call fresh()
      call run('BLOCK 0,0 0,1 1,1 1,0')
      call run('RUN')
      call check(printed('give THERMAL first'), 'RUN without THERMAL is refused')
      call check(.not. allocated(session%model%thermal), 'a refused RUN creates no thermal part')
      call run('THERMAL')
      call run('RUN')
      call check(printed('needs DENSITY and SPECHEAT'), 'RUN on a rigid block without '// &
                 'DENSITY is refused (rigid blocks carry temperatures, Fig. 7-4)')
      call run('GEN -1 2 -1 2 AUTO 0.5')
      call run('RUN')
      call check(printed('needs DENSITY and SPECHEAT'), 'RUN without DENSITY is refused')
      call run('THAPP -1 2 -1 2')
      call check(printed('expected one of CONVECTION'), 'THAPP without a condition is refused')
      call run('THAPP -1 2 -1 2 CONV 1 2 FLUX 1 0')
      call check(printed('expected one of CONVECTION'), 'THAPP with two conditions is refused')
      call check(session%model%thermal%nrec == 0, 'refused THAPP stores nothing')
      call run('INITEM 5')
      call check(printed('expected a range'), 'INITEM without a range is refused')
   end subroutine test_errors

   subroutine test_steady_wall()
      real(wp) :: explicit_error
      call wall()
      call run('RUN STEP 20000 TEMP 1e9')
      call check(printed('RUN stopped by the STEP limit'), 'explicit RUN stops at STEP')
      explicit_error = wall_error()
      ! linear triangles hold the linear steady profile exactly: only the
      ! distance from steady state (time constant ~0.1 s, run ~1000 s) remains
      call check(explicit_error < 1.0e-9_wp*100.0_wp, 'explicit steady wall = series '// &
                 'resistance solution (1e-9 relative)')
      call wall()
      call run('SET THDT 0.01')
      call run('RUN STEP 400 TEMP 1e9 IMPLICIT')
      call check(printed('RUN (implicit)'), 'RUN IMPLICIT runs the implicit scheme')
      call check(wall_error() < 1.0e-6_wp*100.0_wp, 'implicit steady wall = series '// &
                 'resistance solution (1e-6 relative: Jacobi tolerance 1e-7 per step)')
   end subroutine test_steady_wall

   subroutine test_restart_continues()
      real(wp), allocatable :: once(:)
      call wall()
      call run('INITEM 20 0.02 1.1 -1 1')
      call run('RUN STEP 300 TEMP 1e9')
      once = session%model%thermal%temp(1:session%model%thermal%ng)
      call wall()
      call run('INITEM 20 0.02 1.1 -1 1')
      call run('RUN STEP 150 TEMP 1e9')
      call run('SAVE test_thermal_1.sav')
      call fresh()
      call run('RESTART test_thermal_1.sav')
      call check(allocated(session%model%thermal), 'RESTART brings the thermal part back')
      call run('RUN')
      call check(printed('thermal step 300'), 'RUN after RESTART keeps STEP 150 and the count')
      call check(all(session%model%thermal%temp(1:size(once)) == once), &
                 'RUN 150 + SAVE + RESTART + RUN 150 = RUN 300 bit for bit')
      call run('RUN STEP 1 AGE 0')
      call check(printed('AGE limit'), 'RUN AGE stops at once when the age is reached')
      call run('RUN STEP 1 NOAGE')
      call check(printed('STEP limit'), 'NOAGE turns the age test off')
   end subroutine test_restart_continues

   subroutine test_thermal_stress()
      integer(ip) :: z
      real(wp) :: expected
      logical :: ok
      call fresh()
      call run('THERMAL')
      call run('BLOCK 0,0 0,1 1,1 1,0')
      call run('GEN -1 2 -1 2 AUTO 0.5')
      call run('PROP MAT 1 DENS 1 SPEC 1 COND 1 BULK 2 G 1 THEXP 1e-3')
      call run('INITEM 4 -1 2 -1 2')
      ok = all(session%model%geometry%zones%sxx(1:session%model%geometry%zones%n) == 0.0_wp)
      call check(ok, 'INITEM induces no stress')
      call run('TFIX 14 -1 2 -1 2')
      ! Eq. 7-3: d sigma = -K beta dT = -2 * 3e-3 * (14 - 4) = -0.06 (tension +)
      expected = -2.0_wp*3.0e-3_wp*10.0_wp
      ok = .true.
      associate (zn => session%model%geometry%zones)
         do z = 1, zn%n
            ok = ok .and. abs(zn%sxx(z) - expected) < 1.0e-15_wp .and. &
                 abs(zn%syy(z) - expected) < 1.0e-15_wp .and. abs(zn%szz(z) - expected) < 1.0e-15_wp
         end do
      end associate
      call check(ok, 'TFIX 10 degrees above INITEM: sxx = syy = szz = -K 3 alpha dT')
      call run('RUN STEP 10')
      call check_close(session%model%geometry%zones%sxx(1), expected, 1.0e-15_wp, &
                       'uniform fixed temperature: RUN adds no stress')
   end subroutine test_thermal_stress

   subroutine test_thermal_history()
      integer(ip) :: g
      call wall()
      call run('THIST TEMPERATURE 1 0.1 NTCYC 5')
      call check(printed('thermal history 1'), 'THIST TEMPERATURE names its gridpoint')
      g = session%model%thermal%this_gp(1)
      call check_close(session%model%geometry%gridpoints%x(g), 1.0_wp, 1.0e-12_wp, &
                       'THIST takes the gridpoint nearest to (1, 0.1)')
      call run('THIST WRITE 2 x.his')
      call check(printed('no such thermal history'), 'THIST WRITE of a missing history refused')
      call run('RUN STEP 20 TEMP 1e9')
      call check(session%model%thermal%nsamp == 4, 'NTCYC 5: 20 steps give 4 samples')
      call check(session%model%thermal%samp_val(3*20 + 1) == session%model%thermal%temp(g), &
                 'the last sample is the gridpoint temperature after the RUN')
      call run('PRINT THIST 1')
      call check(printed('1 TEMP'), 'PRINT THIST prints the history')
      call run('RESET THIST')
      call check(session%model%thermal%nsamp == 0, 'RESET THIST clears the samples')
   end subroutine test_thermal_history

   !> PRINT CYCLE after a RUN with SET NTHER: the mechanical hand-overs'
   !> steps are counted and their stages timed (issue 19).
   subroutine test_run_timed()
      call fresh()
      call run('THERMAL')
      call run('BLOCK 0,0 0,1 1,1 1,0')
      call run('GEN -1 2 -1 2 AUTO 0.5')
      call run('PROP MAT 1 DENS 1 SPEC 1 COND 1 BULK 2 G 1 THEXP 1e-3')
      call run('TFIX 14 -0.01 0.01 -1 2')
      call run('SET NTHER 4 NMECH 3')
      call run('RUN STEP 8 TEMP 1e9')
      call run('PRINT CYCLE')
      ! 8 thermal steps, a hand-over every 4: 2 hand-overs of NMECH 3 cycles
      call check(printed('Last RUN: 6 mechanical steps in 2 hand-overs'), &
                 'PRINT CYCLE after RUN: the mechanical steps of its hand-overs')
      call check(printed('zone stresses'), 'PRINT CYCLE after RUN: zone stresses timed')
      call check(printed(' %'), 'PRINT CYCLE after RUN: shares of the wall time')
      call run('CYCLE 2')
      call run('PRINT CYCLE')
      call check(printed('Last CYCLE: 2 steps'), 'PRINT CYCLE after RUN then CYCLE: the CYCLE')
   end subroutine test_run_timed

   !> Issue 22: TFIX on every gridpoint, RUN DELT runs (no stability limit
   !> applies, it failed with "no DELT was given"); THIST T is TEMPERATURE
   !> (manual Section 7.4.1: "Temperature x y"; it was read as TYPE); PRINT
   !> BOUNDARY THERMAL lists the boundary gridpoints (it said "not yet");
   !> PLOT THIST (Section 7.4.2) draws (it said "not yet implemented").
   subroutine test_issue22_slips()
      call wall()
      call run('TFIX 50 -1 2 -1 1')
      call run('RUN DELT 0.01 STEP 3')
      call check(.not. printed('no DELT was given'), 'all TFIXed: RUN DELT is not refused')
      call check(printed('STEP limit'), 'all TFIXed: RUN DELT takes its steps')
      call check_close(session%model%thermal%time, 0.03_wp, 1.0e-12_wp, &
                       'all TFIXed: the thermal time advances by STEP x DELT')
      call run('THIST T 0.5 0.1')
      call check(printed('thermal history 1'), 'THIST T x y is THIST TEMPERATURE')
      call run('RUN DELT 0.01 STEP 20')
      call run('PLOT THIST 1')
      call check(printed('Plot ready (THIST'), 'PLOT THIST draws the thermal history')
      call run('PLOT THIST 4')
      call check(printed('thermal history 4 is not defined'), 'PLOT THIST of a missing history')
      call run('PLOT THIST 1 BLOCK')
      call check(printed('cannot be combined'), 'PLOT THIST with a model layer is refused')
      call run('PRINT BOUNDARY THERMAL')
      call check(printed('Thermal boundary: temperature at the gridpoints'), &
                 'PRINT BOUNDARY THERMAL prints the boundary temperatures')
      call check(.not. printed('not yet'), 'PRINT BOUNDARY THERMAL is not "not yet"')
   end subroutine test_issue22_slips

   !> TABLE, PRINT TABLE, TADD (manual Sections 4.5 and 7.4.1): a table
   !> (r, dT) = (0, 10), (1, 0) over the full circle around (0, 0) raises
   !> each free gridpoint by 10 (1 - r) for r < 1, nothing beyond; half the
   !> arc (0 to 90 degrees) only the quadrant; thermal stress -K 3 alpha dT
   !> per zone mean (Eq. 7-3); bad input changes nothing.
   subroutine test_table_tadd()
      integer(ip) :: g
      real(wp) :: r, expected, err
      real(wp), allocatable :: before(:)
      call fresh()
      call run('THERMAL')
      call run('BLOCK -2,-2 -2,2 2,2 2,-2')
      call run('GEN -3 3 -3 3 AUTO 0.5')
      call run('PROP MAT 1 DENS 1 SPEC 1 COND 1 BULK 2 G 1 THEXP 1e-3')
      call run('TADD 1 0 0 180 180')
      call check(printed('table 1 is not defined'), 'TADD before TABLE is refused')
      call run('TABLE 1 0 10 1 0 0.5 3')
      call check(printed('the x values must increase'), 'TABLE with x decreasing is refused')
      call run('TABLE 11 0 1')
      call check(printed('from 1 to 10'), 'TABLE 11 is refused')
      call run('PRINT TABLE')
      call check(printed('no tables'), 'refused TABLEs stored nothing')
      call run('TABLE 1 0 10 1 0')
      call run('PRINT TABLE 1')
      call check(printed('table 1: 2 pair(s)'), 'PRINT TABLE 1 lists the pairs')
      before = session%model%thermal%temp
      call run('TADD 1 0 0 200 180')
      call check(printed('between -180 and 180'), 'TADD angle beyond 180 is refused')
      call check(all(session%model%thermal%temp == before), 'refused TADD changes nothing')
      call run('TADD 1 0 0 180 180')
      err = 0.0_wp
      associate (gp => session%model%geometry%gridpoints)
         do g = 1, gp%n
            r = hypot(gp%x(g), gp%y(g))
            expected = 10.0_wp*max(0.0_wp, 1.0_wp - r)
            err = max(err, abs(session%model%thermal%temp(g) - expected))
         end do
      end associate
      call check(err < 1.0e-12_wp, 'TADD full circle: T = 10 (1 - r) inside r = 1')
      call check(any(session%model%geometry%zones%sxx(1:session%model%geometry%zones%n) < 0.0_wp), &
                 'TADD induces thermal stress')
      before = session%model%thermal%temp
      call run('TADD 1 0 0 0 90')
      err = 0.0_wp
      associate (gp => session%model%geometry%gridpoints)
         do g = 1, gp%n
            r = hypot(gp%x(g), gp%y(g))
            expected = before(g)
            if (gp%x(g) >= 0.0_wp .and. gp%y(g) >= 0.0_wp) &
               expected = expected + 10.0_wp*max(0.0_wp, 1.0_wp - r)
            err = max(err, abs(session%model%thermal%temp(g) - expected))
         end do
      end associate
      call check(err < 1.0e-12_wp, 'TADD 0 to 90 degrees: the first quadrant only')
   end subroutine test_table_tadd

end program test_thermal
