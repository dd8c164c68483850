!> Temperatures of blocks without zones (UDEC manual (ICG1.5, 1989), Section
!> 7.5.2.1, p. 7-25, Fig. 7-4: rigid and simply-deformable blocks are divided
!> into triangles with the centroid as the common vertex, the other vertices
!> at the corners and at contacts with corners of other blocks).
!>
!> References and tolerances:
!> * 1-D transient conduction in a column 0 < y < L = 10 of ten 1 x 1 rigid
!>   blocks (k = 1, rho Cp = 1: diffusivity a = 1), T = 0 at t = 0, y = 0 held
!>   at T0 = 100 (TFIX), all else adiabatic: the slab series (Carslaw and
!>   Jaeger, Sec. 3.3) T = T0 [1 - sum_n 4/((2n+1) pi) sin((2n+1) pi y / (2L))
!>   exp(-(2n+1)^2 pi^2 a t / (4 L^2))] at t = 10, at every corner and
!>   centroid: within 0.5 % of T0 explicit (measured 0.16 %), 1 % implicit with
!>   a step 12 times the explicit one (measured 0.14 %); half the column
!>   zoned (GENERATE QUAD 0.5), half rigid: within 0.5 % of T0 (measured
!>   0.09 %).
!> * Steady state with y = L held at 0 as well: T = T0 (1 - y/L) exactly for
!>   linear triangles, within 1e-6 of T0 (explicit, run to t = 400, 40 time
!>   constants L^2/(pi^2 a)); with THAPP CONV h = 1 to 0 on the top rigid
!>   edge instead, T(L) = T0 / (1 + h L / k) = T0 / 11 within 1e-6 of T0.
!> * SAVE after 120 steps, RESTART, 120 more = 240 steps at once, bit for bit
!>   (corner, centroid temperatures and a THIST at a centroid).
!> * A free simply-deformable block (K = 1e9, G = 6e8: nu = 0.25) heated by
!>   dT = 10 (TFIX) with THEXP alpha = 1e-5 expands freely in plane strain:
!>   exx = eyy = alpha (1 + nu) dT = 1.25e-4 (Eq. 7-3 on the block's uniform
!>   stress, then equilibrium), within 1 %. A rigid block's temperature
!>   changes nothing mechanical (it cannot deform).
!> * A block whose centroid does not see all its edges (a U shape, centroid
!>   in the notch) is cut into ears (it was refused before session 34): RUN
!>   takes its steps, a source heats its corners uniformly by S t / (rho Cp)
!>   (1e-9), and its centroid, outside the block, takes no part; a model
!>   without THERMAL has no thermal part.
program test_thermal_rigid
   use core_kinds, only: wp, ip
   use core_error, only: error_t
   use commands_session, only: session_t, session_init
   use testing_session, only: session_run, lines_contain
   use testing, only: check, check_close, testing_finish
   implicit none

   type(session_t) :: session
   character(len=200), allocatable :: lines(:)
   real(wp), parameter :: t0 = 100.0_wp, length = 10.0_wp

   call test_column_transient()
   call test_column_steady()
   call test_column_restart()
   call test_sdef_expansion()
   call test_refusals()
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

   !> Ten 1 x 1 blocks stacked in 0 < y < 10, thermal properties, y = 0 at T0.
   subroutine column(zoned_half)
      logical, intent(in) :: zoned_half
      integer :: k
      character(len=40) :: cmd
      call fresh()
      call run('BLOCK 0,0 0,10 1,10 1,0')
      do k = 1, 9
         write (cmd, '(a,i0,a,i0)') 'SPLIT -1 ', k, ' 2 ', k
         call run(trim(cmd))
      end do
      if (zoned_half) call run('GEN -1 2 -1 5.01 QUAD 0.5')
      call run('THERMAL')
      call run('PROP MAT 1 DENS 1 SPEC 1 COND 1')
      call run('TFIX 100 -1 2 -0.01 0.01')
   end subroutine column

   real(wp) function series(y, t) result(temp)
      real(wp), intent(in) :: y, t
      integer :: n
      real(wp) :: m, pi
      pi = acos(-1.0_wp)
      temp = 0.0_wp
      do n = 0, 400
         m = real(2*n + 1, wp)
         temp = temp + 4.0_wp/(m*pi)*sin(m*pi*y/(2.0_wp*length))* &
                exp(-m*m*pi*pi*t/(4.0_wp*length*length))
      end do
      temp = t0*(1.0_wp - temp)
   end function series

   !> Largest |T - reference(y)| over the corners and centroids of the blocks
   !> without zones and over the gridpoints; `steady`: the linear profile.
   real(wp) function column_error(t, steady) result(err)
      real(wp), intent(in) :: t
      logical, intent(in) :: steady
      integer(ip) :: i
      err = 0.0_wp
      associate (geo => session%model%geometry, th => session%model%thermal)
         do i = 1, geo%corners%n
            if (.not. geo%corners%live(i)) cycle
            if (geo%blocks%nzone(geo%corners%block(i)) > 0) cycle
            err = max(err, abs(th%ctemp(i) - reference(geo%corners%y(i), t, steady)))
         end do
         do i = 1, geo%blocks%n
            if (.not. geo%blocks%live(i)) cycle
            if (geo%blocks%nzone(i) > 0) cycle
            err = max(err, abs(th%btemp(i) - reference(geo%blocks%yc(i), t, steady)))
         end do
         do i = 1, geo%gridpoints%n
            if (.not. geo%gridpoints%live(i)) cycle
            err = max(err, abs(th%temp(i) - reference(geo%gridpoints%y(i), t, steady)))
         end do
      end associate
   end function column_error

   real(wp) function reference(y, t, steady)
      real(wp), intent(in) :: y, t
      logical, intent(in) :: steady
      if (steady) then
         reference = t0*(1.0_wp - y/length)
      else
         reference = series(y, t)
      end if
   end function reference

   subroutine test_column_transient()
      real(wp) :: err
      character(len=120) :: text
      call column(.false.)
      call run('RUN AGE 10 STEP 100000 TEMP 1e10')
      call check(printed('AGE limit'), 'rigid column: RUN runs to AGE 10')
      call check(printed('32 nodes, 40 triangles'), 'rigid column: Fig. 7-4 mesh, corners '// &
                 'of touching blocks shared (22 corners + 10 centroids, 4 triangles a block)')
      err = column_error(session%model%thermal%time, .false.)
      write (text, '(a,f7.4,a)') 'rigid column explicit vs slab series at t = 10: ', &
         100.0_wp*err/t0, ' % of T0 (0.5 %)'
      call check(err < 0.005_wp*t0, trim(text))
      print '(a)', trim(text)
      call column(.false.)
      call run('RUN AGE 10 STEP 100000 TEMP 1e10 DELT 0.5 IMPLICIT')
      call check(printed('RUN (implicit)'), 'rigid column: RUN IMPLICIT')
      err = column_error(session%model%thermal%time, .false.)
      write (text, '(a,f7.4,a)') 'rigid column implicit (dt 0.5) vs slab series at t = 10: ', &
         100.0_wp*err/t0, ' % of T0 (1 %)'
      call check(err < 0.01_wp*t0, trim(text))
      print '(a)', trim(text)
      call column(.true.)
      call run('RUN AGE 10 STEP 100000 TEMP 1e10')
      err = column_error(session%model%thermal%time, .false.)
      write (text, '(a,f7.4,a)') 'zoned + rigid column explicit vs slab series at t = 10: ', &
         100.0_wp*err/t0, ' % of T0 (0.5 %)'
      call check(err < 0.005_wp*t0, trim(text))
      print '(a)', trim(text)
   end subroutine test_column_transient

   subroutine test_column_steady()
      real(wp) :: err
      integer(ip) :: i
      character(len=120) :: text
      call column(.false.)
      call run('TFIX 0 -1 2 9.99 10.01')
      call run('RUN AGE 400 STEP 100000 TEMP 1e10')
      err = column_error(0.0_wp, .true.)
      write (text, '(a,es10.3,a)') 'rigid column steady = linear profile: error ', err/t0, &
         ' of T0 (1e-6)'
      call check(err < 1.0e-6_wp*t0, trim(text))
      print '(a)', trim(text)
      ! convection h = 1 to 0 degrees on the top edge of the top rigid block:
      ! series resistances L/k + 1/h = 11, T(L) = T0 / 11
      call column(.false.)
      call run('THAPP -1 2 9.99 10.01 CONV 1 0')
      call run('RUN AGE 400 STEP 100000 TEMP 1e10')
      err = 0.0_wp
      associate (co => session%model%geometry%corners, th => session%model%thermal)
         do i = 1, co%n
            if (.not. co%live(i)) cycle
            if (co%y(i) > 9.99_wp) err = max(err, abs(th%ctemp(i) - t0/11.0_wp))
         end do
      end associate
      write (text, '(a,es10.3,a)') 'rigid column, THAPP CONV on a rigid edge: T(L) - T0/11 = ', &
         err/t0, ' of T0 (1e-6)'
      call check(err < 1.0e-6_wp*t0, trim(text))
      print '(a)', trim(text)
   end subroutine test_column_steady

   subroutine test_column_restart()
      real(wp), allocatable :: once_c(:), once_b(:), once_h(:)
      integer(ip) :: nc, nb, ns
      call column(.false.)
      call run('THIST TEMP 0.5 5.5')
      call check(printed('taken at the centroid of block'), 'THIST at a rigid block centroid')
      call run('RUN STEP 240 TEMP 1e10')
      nc = session%model%thermal%nc
      nb = session%model%thermal%nb
      ns = session%model%thermal%nsamp
      once_c = session%model%thermal%ctemp(1:nc)
      once_b = session%model%thermal%btemp(1:nb)
      once_h = session%model%thermal%samp_val(1:ns*20)
      call check(maxval(once_b) > 1.0_wp, 'rigid column: the centroids warm up')
      call column(.false.)
      call run('THIST TEMP 0.5 5.5')
      call run('RUN STEP 120 TEMP 1e10')
      call run('SAVE test_thermal_rigid_1.sav')
      call fresh()
      call run('RESTART test_thermal_rigid_1.sav')
      call check(session%model%thermal%nc == nc .and. session%model%thermal%nb == nb, &
                 'RESTART brings the corner and centroid temperatures back')
      call run('RUN')
      call check(all(session%model%thermal%ctemp(1:nc) == once_c) .and. &
                 all(session%model%thermal%btemp(1:nb) == once_b), &
                 'rigid column: RUN 120 + SAVE + RESTART + RUN 120 = RUN 240 bit for bit')
      call check(session%model%thermal%nsamp == ns, 'THIST samples continue after RESTART')
      if (session%model%thermal%nsamp == ns) &
         call check(all(session%model%thermal%samp_val(1:ns*20) == once_h), &
                    'THIST at a centroid: the same samples after RESTART')
      call run('PRINT TEMPERATURE')
      call check(printed('(centroids)'), 'PRINT TEMPERATURE lists the centroids')
      call run('PRINT THIST')
      call check(printed('(block centroid)'), 'PRINT THIST names a centroid history')
      open (unit=31, file='test_thermal_rigid_1.sav', status='old')
      close (31, status='delete')
   end subroutine test_column_restart

   subroutine test_sdef_expansion()
      real(wp) :: expected, nu
      character(len=120) :: text
      real(wp) :: vx0
      ! a rigid block: the temperature changes nothing mechanical
      call fresh()
      call run('BLOCK 0,0 0,1 1,1 1,0')
      call run('PROP MAT 1 D 2000 K 1E9 G 6E8 THEXP 1e-5 SPEC 1 COND 1')
      call run('THERMAL')
      call run('TFIX 10 -1 2 -1 2')
      vx0 = session%model%geometry%blocks%vx(1)
      call run('CYCLE 10')
      call check(session%model%geometry%blocks%vx(1) == vx0 .and. &
                 session%model%geometry%blocks%fx(1) == 0.0_wp, &
                 'a heated rigid block does not move')
      ! a simply-deformable block expands freely
      call fresh()
      call run('BLOCK 0,0 0,1 1,1 1,0')
      call run('CHANGE SDEF')
      call run('PROP MAT 1 D 2000 K 1E9 G 6E8 THEXP 1e-5 SPEC 1 COND 1')
      call run('THERMAL')
      call run('TFIX 10 -1 2 -1 2')
      call check(printed('4 corner(s) and centroid(s)') .or. printed('5 corner(s) and centroid(s)'), &
                 'TFIX reaches the corners and the centroid of a block without zones')
      call run('DAMP 0.5 100 INTERNAL')
      call run('CYCLE 4000')
      nu = (3.0_wp*1.0e9_wp - 2.0_wp*6.0e8_wp)/(2.0_wp*(3.0_wp*1.0e9_wp + 6.0e8_wp))
      expected = 1.0e-5_wp*(1.0_wp + nu)*10.0_wp
      associate (bl => session%model%geometry%blocks)
         write (text, '(a,2es12.5,a,es12.5,a)') 'SDEF block heated by 10: exx, eyy = ', &
            bl%exx(1), bl%eyy(1), ' vs alpha (1 + nu) dT = ', expected, ' (1 %)'
         print '(a)', trim(text)
         call check(abs(bl%exx(1) - expected) < 0.01_wp*expected .and. &
                    abs(bl%eyy(1) - expected) < 0.01_wp*expected, trim(text))
      end associate
   end subroutine test_sdef_expansion

   subroutine test_refusals()
      call fresh()
      call run('BLOCK 0,0 0,3 1,3 1,1 2,1 2,3 3,3 3,0')
      call run('THERMAL')
      call run('PROP MAT 1 DENS 1 SPEC 1 COND 1')
      call run('INITEM 0 -1 4 -1 4')
      call run('THAPP -1 4 -1 4 SOURCE 2 0')
      call run('RUN STEP 5 DELT 0.01')
      call check(.not. printed('RUN: block 1'), 'a U-shaped rigid block runs (cut into ears)')
      call check(session%model%thermal%nsteps == 5, 'the U-shaped block takes its 5 steps')
      ! every corner heats by S t / (rho Cp) = 2 * 0.05 / 1
      call check(all(abs(session%model%thermal%ctemp(1:8) - 0.1_wp) < 1.0e-9_wp), &
                 'the U-shaped block heats uniformly by S t / (rho Cp)')
      call fresh()
      call run('BLOCK 0,0 0,1 1,1 1,0')
      call run('CYCLE 5')
      call check(.not. allocated(session%model%thermal), 'no THERMAL: no thermal part')
   end subroutine test_refusals

end program test_thermal_rigid
