!> SET ZPRESS x y rad pz (commands_zpress, zones_pressure, model_boundary's
!> zpress_t): zone pressure sources against closed-form answers.
!>
!> Model: one 2 x 2 FDEF block (0..2)^2, K = 1e8, G = 6e7, density 2000,
!> GEN QUAD 0.25 (8 x 8 crossed cells, 256 zones), DAMP AUTO. A pressure p
!> in a zone makes its effective stress sigma - p I.
!>  1. Confined (every boundary gridpoint fixed by BOUNDARY XVEL 0 YVEL 0),
!>     source over the whole block: the pressure forces cancel at interior
!>     gridpoints, so nothing moves and the zone stresses stay 0; the
!>     reactions (gridpoint force sums of the fixed gridpoints) on each side
!>     add up to p L outwards (the pressure integrated over the side).
!>  2. Free block, source over the whole block: equilibrium with a free
!>     boundary needs sigma - p I = 0, i.e. sxx = syy = +p, sxy = 0,
!>     szz = (K - 2G/3) 2e (plane strain) with the uniform strain
!>     e = p / (2 (K + G/3)), and displacement e (x - 1, y - 1).
!>  3. Confined block, source of radius 0.9 at (0, 1) (a half disc at the
!>     left side): the pressurised zones expand; the gridpoints on the
!>     symmetry line y = 1 move away from the source (ux > 0, uy = 0).
!>  4. Kernel and history: LINEAR history captured from BOUNDARY, applied as
!>     k / ncycles; histories back to CONSTANT after the CYCLE.
!>  5. Errors (missing values, rad <= 0, no zones, no zone in the radius; a
!>     rejected SET changes nothing), PRINT BOUNDARY STATE, SAVE / RESTART.
program test_zpress
   use core_kinds, only: wp, ip, i8
   use core_motion, only: stage_args_t
   use core_error, only: error_t
   use model_boundary, only: bh_constant, bh_linear, bh_sine
   use zones_pressure, only: zones_pressure_step
   use commands_session, only: session_t, session_init, session_execute_line
   use testing_session, only: session_run, lines_contain
   use testing, only: check, check_close, check_equal, testing_finish
   implicit none

   type(session_t) :: session
   character(len=200), allocatable :: lines(:)
   real(wp), parameter :: bulk = 1.0e8_wp, shear = 6.0e7_wp, side = 2.0_wp

   call test_confined_whole_block()
   call test_free_whole_block()
   call test_half_source_moves_outward()
   call test_kernel_and_history()
   call test_errors()
   call test_print_and_restart()
   call testing_finish()

contains

   !> Run one command line; `lines` receives what it printed.
   subroutine run(text)
      character(len=*), intent(in) :: text
      call session_run(session, text, lines)
   end subroutine run

   logical function printed(text)
      character(len=*), intent(in) :: text
      printed = lines_contain(lines, text)
   end function printed

   !> The zoned 2 x 2 block (module header).
   subroutine zoned_block()
      type(error_t), allocatable :: error
      call session_init(session, error)
      call check(.not. allocated(error), 'session starts')
      call run('ROUND 0.01')
      call run('BLOCK 0,0 0,2 2,2 2,0')
      call run('PROP MAT=1 D=2000 K=1e8 G=6e7')
      call run('GEN QUAD 0.25')
      call run('DAMP AUTO')
      call check_equal(int(session%model%geometry%zones%n), 256, 'GEN QUAD 0.25: 256 zones')
   end subroutine zoned_block

   !> Case 1. Reference: reactions p L per side (exact: the nodal forces of a
   !> uniform pressure integrate it over the boundary pieces), tolerance 1e-6
   !> relative; zone stresses 0 within 1e-6 p (interior forces cancel to
   !> round-off, so nothing moves).
   subroutine test_confined_whole_block()
      real(wp), parameter :: p = 1.0e6_wp
      real(wp) :: right, left, top, bottom, smax, umax
      integer(ip) :: g, z
      call zoned_block()
      call run('BOUND XVEL 0 YVEL 0')
      call run('SET ZPRESS 1 1 10 1e6')
      call check(printed('source 1') .and. printed('256 zone(s)'), 'confined: 256 zones in source 1')
      call run('CYCLE 500')
      right = 0; left = 0; top = 0; bottom = 0; umax = 0
      associate (gp => session%model%geometry%gridpoints, zn => session%model%geometry%zones)
         do g = 1, gp%n
            if (abs(gp%x(g) - side) < 1.0e-9_wp) right = right + gp%fx(g)
            if (abs(gp%x(g)) < 1.0e-9_wp) left = left + gp%fx(g)
            if (abs(gp%y(g) - side) < 1.0e-9_wp) top = top + gp%fy(g)
            if (abs(gp%y(g)) < 1.0e-9_wp) bottom = bottom + gp%fy(g)
            umax = max(umax, abs(gp%ux(g)), abs(gp%uy(g)))
         end do
         smax = 0
         do z = 1, zn%n
            smax = max(smax, abs(zn%sxx(z)), abs(zn%syy(z)), abs(zn%sxy(z)))
         end do
      end associate
      call check_close(right/(p*side), 1.0_wp, 1.0e-6_wp, 'confined: reaction x = 2 is +p L')
      call check_close(left/(p*side), -1.0_wp, 1.0e-6_wp, 'confined: reaction x = 0 is -p L')
      call check_close(top/(p*side), 1.0_wp, 1.0e-6_wp, 'confined: reaction y = 2 is +p L')
      call check_close(bottom/(p*side), -1.0_wp, 1.0e-6_wp, 'confined: reaction y = 0 is -p L')
      call check(smax <= 1.0e-6_wp*p, 'confined: zone stresses stay 0 (strain 0)')
      ! displacement scale of a mistake: p L / K = 2e-2; round-off far below 1e-12
      call check(umax <= 1.0e-12_wp, 'confined: no gridpoint moves')
   end subroutine test_confined_whole_block

   !> Case 2. Reference in the header. p = 100 keeps the strain (4e-7) small:
   !> the incremental (hypoelastic, current-geometry) zone law leaves a
   !> path-dependent residual of the order of the strain times the transient,
   !> measured 3e-8 p; tolerance 1e-6 relative on stresses and displacements.
   subroutine test_free_whole_block()
      real(wp), parameter :: p = 100.0_wp
      real(wp) :: e, szz
      integer(ip) :: g, z
      logical :: ok_s, ok_u
      call zoned_block()
      call run('SET ZPRESS 1 1 10 100')
      call run('CYCLE 3000')
      e = p/(2.0_wp*(bulk + shear/3.0_wp))
      szz = (bulk - 2.0_wp*shear/3.0_wp)*2.0_wp*e
      ok_s = .true.
      ok_u = .true.
      associate (gp => session%model%geometry%gridpoints, zn => session%model%geometry%zones)
         do z = 1, zn%n
            if (abs(zn%sxx(z) - p) > 1.0e-6_wp*p .or. abs(zn%syy(z) - p) > 1.0e-6_wp*p .or. &
                abs(zn%sxy(z)) > 1.0e-6_wp*p .or. abs(zn%szz(z) - szz) > 1.0e-6_wp*p) then
               if (ok_s) write (*, '(a,i0,4es14.6)') 'zone ', z, zn%sxx(z), zn%syy(z), zn%sxy(z), zn%szz(z)
               ok_s = .false.
            end if
         end do
         do g = 1, gp%n
            ! position now = original + u, so original - 1 = x - ux - 1
            if (abs(gp%ux(g) - e*(gp%x(g) - gp%ux(g) - 1.0_wp)) > 1.0e-6_wp*e .or. &
                abs(gp%uy(g) - e*(gp%y(g) - gp%uy(g) - 1.0_wp)) > 1.0e-6_wp*e) ok_u = .false.
         end do
      end associate
      call check(ok_s, 'free block: sxx = syy = p, sxy = 0, szz = (K - 2G/3) 2e in every zone')
      call check(ok_u, 'free block: uniform expansion u = e (x - xc)')
   end subroutine test_free_whole_block

   !> Case 3. Sign: the source pushes the gridpoints on y = 1 away from (0, 1);
   !> by the symmetry of the mesh about y = 1, uy = 0 there (1e-6 of |ux|).
   subroutine test_half_source_moves_outward()
      integer(ip) :: g, n
      logical :: outward, symmetric
      real(wp) :: umax
      call zoned_block()
      call run('BOUND XVEL 0 YVEL 0')
      call run('SET ZPRESS 0 1 0.9 100')
      call check(.not. printed('256 zone'), 'half source: only part of the zones')
      call run('CYCLE 2000')
      outward = .true.
      symmetric = .true.
      n = 0
      umax = 0
      associate (gp => session%model%geometry%gridpoints)
         do g = 1, gp%n
            umax = max(umax, abs(gp%ux(g)))
         end do
         do g = 1, gp%n
            if (abs(gp%y(g) - 1.0_wp) > 1.0e-6_wp) cycle
            if (gp%x(g) < 1.0e-6_wp .or. gp%x(g) > side - 1.0e-6_wp) cycle
            n = n + 1
            if (.not. gp%ux(g) > 0.0_wp) outward = .false.
            if (abs(gp%uy(g)) > 1.0e-6_wp*umax) symmetric = .false.
         end do
      end associate
      call check_equal(int(n), 7, 'half source: 7 free gridpoints on y = 1')
      call check(umax > 0.0_wp, 'half source: the block deforms')
      call check(outward, 'half source: gridpoints on y = 1 move away from the source (+x)')
      call check(symmetric, 'half source: uy = 0 on the symmetry line')
   end subroutine test_half_source_moves_outward

   !> Case 4. LINEAR from the latest BOUNDARY history; at step 3 of 10 the
   !> kernel applies 0.3 p: right-side force sum 0.3 p L, interior gridpoint
   !> forces 0 (exact up to round-off: 1e-9 p). SINE is captured with its
   !> frequency and duration. After a CYCLE every history is CONSTANT again.
   subroutine test_kernel_and_history()
      real(wp), parameter :: p = 50.0_wp
      real(wp) :: right, interior
      integer(ip) :: g
      call zoned_block()
      call run('SET ZPRESS 1 1 10 50')
      call check(session%model%bound%zp%h(1) == bh_constant, 'no BOUNDARY history: CONSTANT')
      call run('BOUND XVEL 0 YVEL 0 HIST LINEAR')
      call run('SET ZPRESS 1 1 10 50')
      call check(printed('history LIN'), 'SET ZPRESS names the history it captured')
      associate (zp => session%model%bound%zp, geo => session%model%geometry)
         call check_equal(int(zp%n), 2, 'two sources')
         call check(zp%h(2) == bh_linear, 'second source: LINEAR captured')
         ! the kernel alone: switch source 1 off by giving it no pressure
         zp%pz(1) = 0.0_wp
         geo%gridpoints%fx = 0.0_wp
         geo%gridpoints%fy = 0.0_wp
         call zones_pressure_step(session%model%bound, geo, stage_args_t(time=0.0_wp, k=3_i8, &
                                                                    ncycles=10_i8))
         right = 0
         interior = 0
         do g = 1, geo%gridpoints%n
            if (abs(geo%gridpoints%x(g) - side) < 1.0e-9_wp) right = right + geo%gridpoints%fx(g)
            if (geo%gridpoints%corner(g) == 0) interior = max(interior, &
               abs(geo%gridpoints%fx(g)), abs(geo%gridpoints%fy(g)))
         end do
         call check_close(right/(p*side), 0.3_wp, 1.0e-12_wp, 'LINEAR step 3 of 10: 0.3 p L')
         call check(interior <= 1.0e-9_wp*p, 'interior gridpoints: pressure forces cancel')
         zp%pz(1) = p
      end associate
      call run('BOUND HIST SINE 2.0 0.5')
      call run('SET ZPRESS 1 1 10 50')
      associate (zp => session%model%bound%zp)
         call check(zp%h(3) == bh_sine, 'third source: SINE captured')
         call check_close(zp%freq(3), 2.0_wp, 0.0_wp, 'SINE frequency captured')
         call check_close(zp%tload(3), 0.5_wp, 0.0_wp, 'SINE duration captured')
      end associate
      call run('CYCLE 2')
      associate (zp => session%model%bound%zp)
         call check(all(zp%h(1:3) == bh_constant), 'after CYCLE: source histories CONSTANT')
         call check(zp%h_next == bh_constant, 'after CYCLE: history for new sources CONSTANT')
      end associate
      call run('SET ZPRESS 1 1 10 50')
      call check(session%model%bound%zp%h(4) == bh_constant, &
                 'SET ZPRESS after a CYCLE: the expired BOUNDARY history is not taken')
   end subroutine test_kernel_and_history

   subroutine test_errors()
      type(error_t), allocatable :: error
      integer :: nerr
      call session_init(session, error)
      call run('BLOCK 0,0 0,2 2,2 2,0')
      nerr = session%nerrors
      call run('SET ZPRESS 1 1 1 5')
      call check(session%nerrors == nerr + 1, 'no zones: an error')
      call check(printed('SET ZPRESS') .and. printed('no zones'), 'no zones: names the command')
      call run('GEN QUAD 0.5')
      nerr = session%nerrors
      call run('SET ZPRESS 1 1 1')
      call check(session%nerrors == nerr + 1, 'missing pz: an error')
      call check(printed('ZPRESS'), 'missing pz: names the keyword')
      call run('SET ZPRESS 1 1')
      call check(session%nerrors == nerr + 2, 'missing rad and pz: an error')
      call run('SET ZPRESS 1 1 0 5')
      call check(session%nerrors == nerr + 3 .and. printed('rad > 0'), 'rad = 0: an error')
      call run('SET ZPRESS 1 1 -2 5')
      call check(session%nerrors == nerr + 4 .and. printed('rad > 0'), 'rad < 0: an error')
      call run('SET ZPRESS 10 10 1 5')
      call check(session%nerrors == nerr + 5 .and. printed('no zone centroid'), &
                 'no zone in the radius: an error')
      ! a rejected SET changes nothing, not even the keywords before ZPRESS
      call run('SET GRAVITY 0 -10 ZPRESS 1 1 -1 5')
      call check(session%nerrors == nerr + 6, 'SET GRAVITY ... bad ZPRESS: an error')
      call check(session%model%gravity(2) == 0.0_wp, 'rejected SET: gravity unchanged')
      call check_equal(int(session%model%bound%zp%n), 0, 'rejected SETs: no source')
      call run('SET ZPRESS 1 1 0.6 5 ZPRESS 1 1 10 7')
      call check_equal(int(session%model%bound%zp%n), 2, 'two ZPRESS on one SET line')
   end subroutine test_errors

   subroutine test_print_and_restart()
      character(len=*), parameter :: file = 'test_zpress.sav'
      integer :: u
      call zoned_block()
      call run('SET ZPRESS 1 1 0.6 5')
      call run('PRINT BOUNDARY')
      call check(printed('no boundary conditions'), 'PRINT BOUNDARY before BOUNDARY: says so')
      call check(printed('ZPRESS SOURCES'), 'PRINT BOUNDARY: lists the sources without BOUNDARY')
      call run('BOUND XVEL 0')
      call run('PRINT BOUNDARY STATE')
      call check(printed('ZPRESS SOURCES') .and. printed('6.00000E-01'), &
                 'PRINT BOUNDARY STATE: source table with the radius')
      call run('PRINT BOUNDARY FORCES')
      call check(.not. printed('ZPRESS SOURCES'), 'PRINT BOUNDARY FORCES: no source table')
      call run('SAVE '//file)
      call run('NEW')
      call check_equal(int(session%model%bound%zp%n), 0, 'NEW: no source')
      call run('RESTART '//file)
      associate (zp => session%model%bound%zp)
         call check_equal(int(zp%n), 1, 'RESTART: the source is back')
         if (zp%n == 1) then
            call check_close(zp%pz(1), 5.0_wp, 0.0_wp, 'RESTART: its pressure')
            call check_equal(int(zp%nz), int(zp%nzone(1)), 'RESTART: its zone list')
         end if
      end associate
      open (newunit=u, file=file, status='old')
      close (u, status='delete')
   end subroutine test_print_and_restart

end program test_zpress
