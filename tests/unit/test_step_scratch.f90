!> The contact phase's step scratch (issue 23, contact_mechanics'
!> contact_work_t%scratch): the edge frames of the geometry pass and the
!> packed blocks of the force pass share one array, so each pass must write
!> what it reads before reading it. Two copies of a cycled, cut wall take
!> the same contact steps (geometry pass, force pass, twice); in the second
!> the scratch is filled with a poison value before every pass. A pass that
!> read the other's leftovers, or a column it did not write, would give
!> other gaps, normals, contact forces or block force sums: all must be the
!> same to the last bit. Also checked: the scratch is one array, sized for
!> the larger of the two uses (4 reals a corner id, 8 a block id), not for
!> both. Run on one thread (force sums in the rigid loop's pack) and with
!> the split force pass of two threads (pack read, sums in work%cf).
!> Reference: the passes' own one-thread results. Tolerance: none.
program test_step_scratch
   use core_kinds, only: wp, ip
   use core_error, only: error_t
   use commands_session, only: session_t
   use contact_mechanics, only: contact_work_t, contact_work_setup, contact_groups_build, &
                                contact_geometry_pass, contact_force_pass
   use model_geometry, only: geometry_t
   use testing, only: check, check_equal, testing_finish
   use testing_session, only: session_new_quiet, session_lines
   implicit none

   call test_scratch('small wall, one thread', 12, 1)
   ! more than 4000 contacts: the split force pass and threaded geometry chunks
   call test_scratch('large wall, split pass', 40, 2)
   call testing_finish()

contains

   subroutine test_scratch(what, n, nthreads)
      character(len=*), intent(in) :: what
      integer, intent(in) :: n, nthreads
      type(session_t) :: s
      type(geometry_t) :: ga, gb
      type(contact_work_t) :: wa, wb
      character(len=60) :: box, js1, js2
      integer(ip) :: bad_a, bad_b, ndiff
      integer :: k
      real(wp) :: dt
      write (box, '(a,i0,a,i0,a,i0,a,i0,a)') 'BLOCK 0,0 0,', n, ' ', n, ',', n, ' ', n, ',0'
      write (js1, '(a,i0,a)') 'JSET 0,0 ', 10*n, ',0 0,0 1,0 0,0'
      write (js2, '(a,i0,a)') 'JSET 90,0 ', 10*n, ',0 0,0 1,0 0.5,0'
      call session_new_quiet(s)
      call session_lines(s, [character(len=60) :: 'ROUND 0.01', box, js1, js2, &
                             'PROP MAT=1 DENS=2500 JKN=1E10 JKS=1E10 JFRIC=0.5', &
                             'GRAV 0.5 -10', 'FIX -1,1000 -1,0.5', 'CYCLE 20'])
      call check(s%nerrors == 0, what//': commands accepted')
      dt = s%model%mech%dt
      call check(dt > 0.0_wp, what//': the CYCLE set a time step')
      ga = s%model%geometry
      gb = s%model%geometry
      call prepare(what, s, wa, ga, nthreads)
      call prepare(what, s, wb, gb, nthreads)
      call check(wa%split .eqv. (nthreads > 1), what//': the force pass split as intended')
      do k = 1, 2
         call contact_geometry_pass(wa, ga, huge(1.0_wp), bad_a)
         call poison(wb, gb)
         call contact_geometry_pass(wb, gb, huge(1.0_wp), bad_b)
         call check_equal(bad_b, bad_a, what//': same worst overlap')
         call contact_force_pass(wa, ga, dt, .true.)
         call poison(wb, gb)
         call contact_force_pass(wb, gb, dt, .true.)
      end do
      call check(size(wa%scratch) == max(4_ip*max(16_ip, ga%corners%n), 8_ip*max(16_ip, ga%blocks%n)), &
                 what//': one scratch, sized for the larger use')
      call check(ga%contacts%n > 4*n*n, what//': the wall''s contacts')
      ndiff = count(ga%contacts%gap(1:ga%contacts%n) /= gb%contacts%gap(1:gb%contacts%n)) &
              + count(ga%contacts%nx(1:ga%contacts%n) /= gb%contacts%nx(1:gb%contacts%n)) &
              + count(ga%contacts%ny(1:ga%contacts%n) /= gb%contacts%ny(1:gb%contacts%n)) &
              + count(ga%contacts%x(1:ga%contacts%n) /= gb%contacts%x(1:gb%contacts%n)) &
              + count(wa%gap_new(1:ga%contacts%n) /= wb%gap_new(1:gb%contacts%n))
      call check_equal(ndiff, 0_ip, what//': same contact geometry')
      ndiff = count(ga%contacts%state%fn(1:ga%contacts%n) /= gb%contacts%state%fn(1:gb%contacts%n)) &
              + count(ga%contacts%state%fs(1:ga%contacts%n) /= gb%contacts%state%fs(1:gb%contacts%n))
      call check_equal(ndiff, 0_ip, what//': same contact forces')
      call check(any(ga%contacts%state%fn(1:ga%contacts%n) /= 0.0_wp), what//': the contacts carry load')
      ndiff = count(ga%blocks%fx(1:ga%blocks%n) /= gb%blocks%fx(1:gb%blocks%n)) &
              + count(ga%blocks%fy(1:ga%blocks%n) /= gb%blocks%fy(1:gb%blocks%n)) &
              + count(ga%blocks%fm(1:ga%blocks%n) /= gb%blocks%fm(1:gb%blocks%n))
      call check_equal(ndiff, 0_ip, what//': same block force sums')

   end subroutine test_scratch

   !> The scratch filled with a value no pass computes (allocated first, at
   !> its size, before the first pass).
   subroutine poison(w, g)
      type(contact_work_t), intent(inout) :: w
      type(geometry_t), intent(in) :: g
      if (.not. allocated(w%scratch)) &
         allocate (w%scratch(max(4_ip*max(16_ip, g%corners%n), 8_ip*max(16_ip, g%blocks%n))))
      w%scratch = -7.0e300_wp
   end subroutine poison

   !> The contact work of a CYCLE's set-up (engine_cycle's cycle_prepare) on
   !> `nthreads` threads.
   subroutine prepare(what, s, w, g, nthreads)
      character(len=*), intent(in) :: what
      type(session_t), intent(inout) :: s
      type(contact_work_t), intent(inout) :: w
      type(geometry_t), intent(inout) :: g
      integer, intent(in) :: nthreads
      type(error_t), allocatable :: error
      call contact_work_setup(w, g, error)
      call check(.not. allocated(error), what//': work set up')
      w%nthreads = nthreads
      w%switch_tol = 1.0e-3_wp*s%model%geometry%tol
      call contact_groups_build(w, g, s%model%materials, s%model%mech%clemin, &
                                s%model%mech%clemin_auto, error)
      call check(.not. allocated(error), what//': groups built')
   end subroutine prepare

end program test_step_scratch
