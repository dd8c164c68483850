!> Output for fully-deformable blocks: PRINT GRIDPOINT / ZONE / MAX /
!> STRESS, HISTORY at zones and gridpoints, PLOT zone layers and contours,
!> the strength/stress ratios. The zoning is built by hand (4 x 2 model
!> split at x = 2; the left block is zoned as a fan of four triangles around
!> its centre (1, 1), the right block stays rigid).
program test_zone_output
   use core_kinds, only: wp, ip
   use model_zones, only: zones_add_gridpoint, zones_add_zone, zone_at_failure, &
                          zone_failed_past, zone_tension
   use model_history, only: hist_sxx, hist_syy, hist_gxdis, hist_xdis, hist_gyvel
   use model_zone_fields, only: principal_stresses, mohr_ratio, hoek_ratio, zone_area, &
                                zone_centroid, zone_strength_ratio, gridpoint_average, ratio_cap
   use engine_history, only: history_values
   use plot_scene, only: item_fill, item_polyline, item_text, legend_line, legend_bar
   use plot_layers, only: layer_options_t
   use plot_zones, only: plot_zone_layer_names, contour_levels, clip_band, zone_field
   use commands_session, only: session_t, session_init, session_execute_line
   use testing_session, only: session_run, lines_contain
   use testing, only: check, check_close, check_equal, check_string, testing_finish
   implicit none

   type(session_t) :: session
   character(len=200), allocatable :: lines(:)
   integer(ip) :: bz, br, zb, zl, gc
   real(wp), parameter :: tan30 = 0.5773502691896258_wp
   real(wp), parameter :: deg = 0.017453292519943295_wp   !< radians per degree

   call build_model()
   call test_principal_and_ratios()
   call test_print_tables()
   call test_print_stress()
   call test_history()
   call test_contours()
   call test_plots()
   call testing_finish()

contains

   subroutine run(text)
      character(len=*), intent(in) :: text
      call session_run(session, text, lines)
   end subroutine run

   integer function count_containing(text) result(n)
      character(len=*), intent(in) :: text
      integer :: i
      n = 0
      do i = 1, size(lines)
         if (index(lines(i), text) > 0) n = n + 1
      end do
   end function count_containing

   !> First captured line whose first two integers are (id, block); 0 if none.
   integer function row_of(id, block) result(r)
      integer(ip), intent(in) :: id, block
      integer :: i, a, b, ios
      r = 0
      do i = 1, size(lines)
         read (lines(i), *, iostat=ios) a, b
         if (ios /= 0) cycle
         if (a == id .and. b == block) then
            r = i
            return
         end if
      end do
   end function row_of

   !> Two blocks; the left one zoned by hand (what GENERATE will do).
   subroutine build_model()
      use core_error, only: error_t
      type(error_t), allocatable :: error
      integer(ip) :: b, c, k, g, gcentre, ring(4), gring(4), z
      real(wp) :: xc, yc
      call session_init(session, error)
      call check(.not. allocated(error), 'session starts')
      call run('BLOCK (0,0) (0,2) (4,2) (4,0)')
      call run('SPLIT (2,-1) (2,3)')
      call run('PROP MAT=1 DENS=2000 COH=1 FRIC=0.5773502691896258 TENS=1')
      bz = 0
      br = 0
      associate (geo => session%model%geometry)
         do b = 1, geo%blocks%n
            if (.not. geo%blocks%live(b)) cycle
            if (geo%blocks%xc(b) < 2.0_wp) then
               bz = b
            else
               br = b
            end if
         end do
         call check(bz > 0 .and. br > 0, 'two blocks, left and right of x = 2')
         call check_equal(int(geo%blocks%ncorner(bz)), 4, 'left block has 4 corners')
         geo%blocks%fdef(bz) = .true.
         geo%blocks%gfirst(bz) = geo%gridpoints%n + 1
         c = geo%blocks%first_corner(bz)
         do k = 1, 4
            ring(k) = c
            call zones_add_gridpoint(geo%gridpoints, bz, c, geo%corners%x(c), geo%corners%y(c), g)
            geo%corners%gp(c) = g
            gring(k) = g
            c = geo%corners%next(c)
         end do
         call zones_add_gridpoint(geo%gridpoints, bz, 0_ip, 1.0_wp, 1.0_wp, gcentre)
         gc = gcentre
         geo%blocks%ngp(bz) = 5
         geo%blocks%zfirst(bz) = geo%zones%n + 1
         do k = 1, 4
            ! the corner ring is clockwise: (centre, next, this) is counter-clockwise
            call zones_add_zone(geo%zones, bz, gcentre, gring(modulo(k, 4) + 1), gring(k), z)
         end do
         geo%blocks%nzone(bz) = 4
         geo%gridpoints%mass(1:5) = 500.0_wp
         ! the bottom zone (centroid (1, 1/3)) and the left zone (centroid (1/3, 1))
         zb = 0
         zl = 0
         do z = 1, 4
            call check_close(zone_area(geo, z), 1.0_wp, 1.0e-12_wp, 'fan zone area 1 (of 4)')
            call zone_centroid(geo, z, xc, yc)
            if (abs(xc - 1.0_wp) < 1.0e-12_wp .and. abs(yc - 1.0_wp/3.0_wp) < 1.0e-12_wp) zb = z
            if (abs(xc - 1.0_wp/3.0_wp) < 1.0e-12_wp .and. abs(yc - 1.0_wp) < 1.0e-12_wp) zl = z
         end do
         call check(zb > 0 .and. zl > 0, 'bottom and left zones found')
         ! stresses: every zone (-3, 1, -1) except the left one; the bottom
         ! zone at failure, the left one in tension
         geo%zones%sxx(1:4) = -3.0_wp
         geo%zones%sxy(1:4) = 1.0_wp
         geo%zones%syy(1:4) = -1.0_wp
         geo%zones%szz(1:4) = -2.0_wp
         geo%zones%state(zb) = zone_at_failure
         geo%zones%sxx(zl) = 2.0_wp
         geo%zones%sxy(zl) = 0.0_wp
         geo%zones%syy(zl) = -4.0_wp
         geo%zones%state(zl) = zone_tension
         ! gridpoint motion: displacement = (2x + 3y, -x), velocity (0, y)
         do g = 1, 5
            geo%gridpoints%ux(g) = 2.0_wp*geo%gridpoints%x(g) + 3.0_wp*geo%gridpoints%y(g)
            geo%gridpoints%uy(g) = -geo%gridpoints%x(g)
            geo%gridpoints%vy(g) = geo%gridpoints%y(g)
         end do
      end associate
   end subroutine build_model

   subroutine test_principal_and_ratios()
      real(wp) :: smin, smax, angle, f
      ! (sxx, syy, sxy) = (-3, -1, 1): centre -2, radius sqrt(2); smax is at
      ! 0.5 atan2(2, -2) = 67.5 deg, smin perpendicular: -22.5 deg. Check by
      ! the normal stress at -22.5 deg: -3 cos^2 - sin^2 + 2 sin cos = smin.
      call principal_stresses(-3.0_wp, -1.0_wp, 1.0_wp, smin, smax, angle)
      call check_close(smin, -2.0_wp - sqrt(2.0_wp), 1.0e-12_wp, 'smin of (-3,-1,1)')
      call check_close(smax, -2.0_wp + sqrt(2.0_wp), 1.0e-12_wp, 'smax of (-3,-1,1)')
      call check_close(angle, -22.5_wp, 1.0e-10_wp, 'angle of smin of (-3,-1,1)')
      call check_close(-3.0_wp*cos(angle*deg)**2 - sin(angle*deg)**2 + &
                       2.0_wp*sin(angle*deg)*cos(angle*deg), smin, 1.0e-12_wp, &
                       'normal stress along the smin direction is smin')
      call principal_stresses(2.0_wp, -4.0_wp, 0.0_wp, smin, smax, angle)
      call check_close(angle, 90.0_wp, 1.0e-12_wp, 'smin along y: angle 90 (range (-90,90])')
      ! Mohr-Coulomb, c = 1, phi = 30 deg: N = (1+sin)/(1-sin) = 3, so with
      ! s3 = 2 (compression +) the failure s1 = 3*2 + 2*1*sqrt(3) = 9.4641;
      ! r_b = (9.4641 - 2)/2 = 3.7321, r_a = (10 - 2)/2 = 4: F = 0.93301
      f = mohr_ratio(-10.0_wp, -2.0_wp, 1.0_wp, tan30, 1.0_wp)
      call check_close(f, (3.0_wp*2.0_wp + 2.0_wp*sqrt(3.0_wp) - 2.0_wp)/8.0_wp, 1.0e-12_wp, &
                       'MOHR ratio, confined compression')
      ! tension 0.5 below the cut-off min(TENS 1, c/tan phi 1.732): s3 = -0.5,
      ! s1f = 3*(-0.5) + 2 sqrt(3) = 1.9641, r_b = 1.2321, r_a = 1.75, F < 0
      f = mohr_ratio(-3.0_wp, 0.5_wp, 1.0_wp, tan30, 1.0_wp)
      call check_close(f, -(-1.5_wp + 2.0_wp*sqrt(3.0_wp) + 0.5_wp)/2.0_wp/1.75_wp, 1.0e-12_wp, &
                       'MOHR ratio negative in tension')
      call check_close(mohr_ratio(-3.0_wp, 1.5_wp, 1.0_wp, tan30, 1.0_wp), 0.0_wp, 0.0_wp, &
                       'MOHR ratio 0 beyond the tension cut-off')
      call check_close(mohr_ratio(-3.0_wp, -3.0_wp, 1.0_wp, tan30, 1.0_wp), ratio_cap, 0.0_wp, &
                       'MOHR ratio capped for an isotropic state')
      ! Hoek-Brown m 10, s 1, ucs 100, s3 = 2: r_b = sqrt(10*100*2 + 1e4)/2
      f = hoek_ratio(-10.0_wp, -2.0_wp, 1.0_wp, 10.0_wp, 100.0_wp)
      call check_close(f, sqrt(12000.0_wp)/2.0_wp/4.0_wp, 1.0e-12_wp, 'HOEK ratio')
      call check_close(hoek_ratio(-10.0_wp, 10.5_wp, 1.0_wp, 10.0_wp, 100.0_wp), 0.0_wp, 0.0_wp, &
                       'HOEK ratio 0 beyond s ucs / m = 10')
      call check(hoek_ratio(-10.0_wp, 5.0_wp, 1.0_wp, 10.0_wp, 100.0_wp) < 0.0_wp, &
                 'HOEK ratio negative in tension')
      ! zone ratio with the block's material (COH 1, FRIC tan 30, TENS 1):
      ! the bottom zone (-3,-1,1): s3 = 0.5858, s1 = 3.4142; s1f = 3 s3 + 2 sqrt 3
      associate (geo => session%model%geometry)
         f = zone_strength_ratio(geo, session%model%materials, zb, 'MOHR')
         call check_close(f, (2.0_wp*(2.0_wp - sqrt(2.0_wp)) + 2.0_wp*sqrt(3.0_wp))/ &
                          (2.0_wp*sqrt(2.0_wp)), 1.0e-12_wp, 'zone MOHR ratio with block material')
      end associate
   end subroutine test_principal_and_ratios

   subroutine test_print_tables()
      integer :: r, ios, st, i
      integer(ip) :: id, blk, g1, g2, g3, corner
      real(wp) :: v(8), angle, area, mass
      character(len=20) :: word, fix
      call run('PRINT ZONE STRESS')
      r = row_of(zb, bz)
      call check(r > 0, 'PRINT ZONE STRESS lists the bottom zone')
      if (r > 0) then
         read (lines(r), *, iostat=ios) id, blk, v(1:6), angle, st, word
         call check(ios == 0, 'zone stress row reads back')
         ! es14.5: 6 significant digits
         call check_close(v(5), -2.0_wp - sqrt(2.0_wp), 1.0e-5_wp, 'printed SMIN')
         call check_close(v(6), -2.0_wp + sqrt(2.0_wp), 1.0e-5_wp, 'printed SMAX')
         call check_close(angle, -22.5_wp, 0.05_wp, 'printed angle (f8.1)')
         call check_equal(st, 1, 'printed indicator 1')
         call check_string(trim(word), 'at-failure', 'indicator text at failure')
      end if
      r = row_of(zl, bz)
      if (r > 0) then
         read (lines(r), *, iostat=ios) id, blk, v(1:6), angle, st, word
         call check_string(trim(word), 'tension', 'indicator text tension')
         call check_equal(st, 3, 'printed indicator 3')
      end if
      call check(index(lines(1), 'PLASTICITY') > 0, 'zone stress header')
      call run('PRINT ZONE STATE')
      r = row_of(zb, bz)
      call check(r > 0, 'PRINT ZONE STATE lists the bottom zone')
      if (r > 0) then
         read (lines(r), *, iostat=ios) id, blk, g1, g2, g3, area, mass
         call check_close(area, 1.0_wp, 1.0e-5_wp, 'printed zone area')
         ! unscaled mass = density 2000 x area 1
         call check_close(mass, 2000.0_wp, 1.0e-2_wp, 'printed zone mass')
         call check_equal(int(g1), int(gc), 'first vertex is the centre gridpoint')
      end if
      call run('PRINT ZONE')
      call check_equal(count_containing('    ZONE   BLOCK'), 2, 'PRINT ZONE: both tables')
      call run('PRINT GRIDPOINT STATE')
      call check_equal(size(lines), 6, 'PRINT GRIDPOINT STATE: header and 5 rows')
      r = row_of(gc, bz)
      if (r > 0) then
         read (lines(r), *, iostat=ios) id, blk, corner, v(1:3), fix
         call check_equal(int(corner), 0, 'the centre gridpoint has no corner link')
         call check_close(v(3), 500.0_wp, 1.0e-3_wp, 'printed gridpoint mass')
         call check_string(trim(fix), '--', 'no velocity fixed')
      end if
      do i = 1, 4
         r = row_of(int(i, ip), bz)
         if (r > 0) then
            read (lines(r), *, iostat=ios) id, blk, corner
            call check_equal(int(session%model%geometry%corners%gp(corner)), i, &
                             'corner link of a boundary gridpoint points back')
         end if
      end do
      ! box range (inclusive; no gridpoint on its edges): only (1, 1)
      call run('PRINT 0.5 1.5 0.5 1.5 GRIDPOINT DISP')
      call check_equal(size(lines), 2, 'ranged PRINT GRIDPOINT DISP: one row')
      r = row_of(gc, bz)
      if (r > 0) then
         read (lines(r), *, iostat=ios) id, blk, v(1:6)
         call check_close(v(3), 5.0_wp, 1.0e-5_wp, 'printed x-displacement 2x+3y at (1,1)')
         call check_close(v(6), 1.0_wp, 1.0e-5_wp, 'printed y-velocity y at (1,1)')
      end if
      call run('PRINT GRIDPOINT')
      call check_equal(count_containing('  GRIDPT   BLOCK'), 3, 'PRINT GRIDPOINT: three tables')
      call run('PRINT MAT 2 ZONE STATE')
      call check_equal(size(lines), 1, 'PRINT MAT 2 ZONE: header only')
      call run('PRINT MAX')
      call check_equal(count_containing('number of zones'), 1, 'PRINT MAX counts zones')
      r = 0
      do i = 1, size(lines)
         if (index(lines(i), 'max gridpoint displacement') > 0) r = i
      end do
      call check(r > 0, 'PRINT MAX: max gridpoint displacement line')
      if (r > 0) then
         ! |(2x+3y, -x)| is largest at (2, 2): |(10, -2)| = sqrt(104)
         read (lines(r)(31:44), *) v(1)
         call check_close(v(1), sqrt(104.0_wp), 1.0e-4_wp, 'max gridpoint displacement')
      end if
      r = 0
      do i = 1, size(lines)
         if (index(lines(i), 'min principal stress') > 0) r = i
      end do
      if (r > 0) then
         read (lines(r)(31:44), *) v(1)
         call check_close(v(1), -4.0_wp, 1.0e-5_wp, 'PRINT MAX: min principal stress (left zone)')
      end if
      ! The block lines of velocity, displacement and unbalanced force are
      ! rigid-block quantities: a zoned block moves by its gridpoints and has
      ! no block force, so its weight must not show as an unbalanced force.
      ! Rigid block: m 100, g 10 -> |(fx, fy + m g)| = 1000 (exact in es14.5);
      ! the zoned block (mass 8000) would read 80000.
      associate (bl => session%model%geometry%blocks)
         session%model%gravity = [0.0_wp, -10.0_wp]
         bl%mass(bz) = 8000.0_wp
         bl%mass(br) = 100.0_wp
         bl%fx(bz) = 0.0_wp; bl%fy(bz) = 0.0_wp; bl%fx(br) = 0.0_wp; bl%fy(br) = 0.0_wp
         call run('PRINT MAX')
         r = 0
         do i = 1, size(lines)
            if (index(lines(i), 'max unbalanced force') > 0) r = i
         end do
         call check(r > 0, 'PRINT MAX: unbalanced force line (one rigid block)')
         if (r > 0) then
            read (lines(r)(31:44), *) v(1)
            call check_close(v(1), 1000.0_wp, 1.0e-9_wp, 'PRINT MAX: unbalanced force of the rigid block')
            read (lines(r)(54:61), *) i
            call check_equal(int(i, ip), br, 'PRINT MAX: unbalanced force names the rigid block')
         end if
         ! only the zoned block in the range: no block motion lines at all
         call run('PRINT -1 1.9 -1 3 MAX')
         call check_equal(count_containing('max unbalanced force'), 0, &
                          'PRINT MAX over the zoned block only: no block unbalanced force')
         call check_equal(count_containing('max block velocity'), 0, &
                          'PRINT MAX over the zoned block only: no block velocity')
         call check_equal(count_containing('block mass, minimum'), 1, &
                          'PRINT MAX over the zoned block only: its mass is listed')
         session%model%gravity = 0.0_wp
         bl%mass(bz) = 0.0_wp
         bl%mass(br) = 0.0_wp
      end associate
   end subroutine test_print_tables

   subroutine test_print_stress()
      integer :: before, u, ios, nfile, i, r
      integer(ip) :: z
      character(len=200) :: line
      real(wp) :: x, y, smin, smax, angle
      before = session%nerrors
      ! 4 x 2 cell centres: x = 0.5 1.5 2.5 3.5, y = 0.5 1.5
      call run('PRINT STRESS 0 4 0 2 4 2')
      call check_equal(session%nerrors, before, 'PRINT STRESS runs')
      call check_equal(count_containing('outside'), 4, 'points in the rigid block are outside')
      ! (1.5, 0.5) lies inside the bottom zone (0,0) (2,0) (1,1) only
      r = 0
      do i = 1, size(lines)
         read (lines(i), *, iostat=ios) x, y, smin, smax, angle, z
         if (ios /= 0) cycle
         if (abs(x - 1.5_wp) < 1.0e-9_wp .and. abs(y - 0.5_wp) < 1.0e-9_wp) then
            r = i
            call check_equal(int(z), int(zb), 'point (1.5, 0.5) in the bottom zone')
            call check_close(smin, -2.0_wp - sqrt(2.0_wp), 1.0e-5_wp, 'grid point smin')
         end if
      end do
      call check(r > 0, 'grid point (1.5, 0.5) printed')
      open (newunit=u, file='STRESS', status='old', action='read', iostat=ios)
      call check(ios == 0, 'PRINT STRESS writes the file STRESS')
      if (ios == 0) then
         nfile = 0
         do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            nfile = nfile + 1
            if (nfile + 0 <= size(lines)) call check_string(trim(line), trim(lines(nfile)), &
                                                             'file line equals printed line')
         end do
         close (u, status='delete')
         ! header, column line, 8 points
         call check_equal(nfile, 10, 'STRESS file: header, columns, 8 points')
      end if
      before = session%nerrors
      call run('PRINT STRESS 1 0 0 1 2 2')
      call check_equal(session%nerrors, before + 1, 'PRINT STRESS xl > xu is an error')
      call run('PRINT STRESS')
      call check_equal(session%nerrors, before + 2, 'PRINT STRESS without the grid is an error')
   end subroutine test_print_stress

   subroutine test_history()
      real(wp), allocatable :: vals(:)
      integer :: n0
      associate (h => session%model%hist, geo => session%model%geometry)
         n0 = h%n
         ! (1, 0.2): nearest centroid is the bottom zone's (1, 1/3)
         call run('HISTORY SXX 1 0.2')
         call check_equal(h%kind(n0 + 1), hist_sxx, 'SXX kind')
         call check_equal(int(h%entity(n0 + 1)), int(zb), 'SXX in the nearest zone')
         call check(count_containing('taken at zone') == 1, 'HISTORY reports the zone')
         ! (1, 1) is equally near all four centroids: the lowest id wins
         call run('HISTORY SYX 1 1')
         call check_equal(h%kind(n0 + 2), hist_syy, 'SYX is the yy-stress (manual typo)')
         call check_equal(int(h%entity(n0 + 2)), 1, 'tie: lowest zone id')
         ! (1.8, 1): centre gridpoint at 0.8 beats corners (2,0) (2,2) at 1.02
         call run('HISTORY XDIS 1.8 1')
         call check_equal(h%kind(n0 + 3), hist_gxdis, 'XDIS at a gridpoint')
         call check_equal(int(h%entity(n0 + 3)), int(gc), 'nearest gridpoint: the centre')
         ! (3.9, 1.9): rigid corner (4, 2)
         call run('HISTORY XDIS 3.9 1.9')
         call check_equal(h%kind(n0 + 4), hist_xdis, 'XDIS at a rigid corner')
         call check(geo%corners%block(h%entity(n0 + 4)) == br, 'corner of the rigid block')
         ! (1.9, 1.9): gridpoint (2,2) and rigid corner (2,2) tie: the corner
         call run('HISTORY XDIS 1.9 1.9')
         call check_equal(h%kind(n0 + 5), hist_xdis, 'tie gridpoint/corner: the corner')
         call run('HISTORY YVEL 1.2 0.9')
         call check_equal(h%kind(n0 + 6), hist_gyvel, 'YVEL at a gridpoint')
         allocate (vals(h%n))
         call history_values(h, geo, session%model%mech, vals)
         call check_close(vals(n0 + 1), -3.0_wp, 0.0_wp, 'SXX value of the bottom zone')
         call check_close(vals(n0 + 3), 5.0_wp, 0.0_wp, 'XDIS of the centre gridpoint: 2+3')
         call check_close(vals(n0 + 6), 1.0_wp, 0.0_wp, 'YVEL of the centre gridpoint')
         ! the zone goes dead: located again at the next sample
         geo%zones%live(zb) = .false.
         call history_values(h, geo, session%model%mech, vals)
         call check(h%entity(n0 + 1) /= zb .and. h%entity(n0 + 1) > 0, &
                    'dead zone: the nearest live zone is taken')
         geo%zones%live(zb) = .true.
      end associate
   end subroutine test_history

   subroutine test_contours()
      type(layer_options_t) :: opts
      real(wp), allocatable :: edges(:), gval(:), zval(:)
      real(wp) :: interval, x(3), y(3), f(3), px(7), py(7), area, total
      integer :: n, k, i
      logical :: on_level
      ! levels: data 0.3 .. 7.7, default interval: the 1-2-5 number below
      ! 7.4/8 is 0.5, which gives 14.8 > 12 bands, doubled to 1; edges 0 .. 8
      call contour_levels(0.3_wp, 7.7_wp, opts, edges, interval)
      call check_close(interval, 1.0_wp, 0.0_wp, 'default interval')
      call check_close(edges(1), 0.0_wp, 0.0_wp, 'first edge')
      call check_close(edges(size(edges)), 8.0_wp, 1.0e-12_wp, 'last edge')
      opts%has_interval = .true.
      opts%interval = 2.0_wp
      call contour_levels(0.3_wp, 7.7_wp, opts, edges, interval)
      call check_equal(size(edges), 5, 'INTERVAL 2: edges 0 2 4 6 8')
      opts%has_max = .true.
      opts%vmax = 5.0_wp
      opts%vmin = 1.0_wp
      call contour_levels(0.3_wp, 7.7_wp, opts, edges, interval)
      call check(size(edges) == 4, 'MAX 5 1 INTERVAL 2: edges 1 2 4 5')
      if (size(edges) == 4) call check(all(abs(edges - [1.0_wp, 2.0_wp, 4.0_wp, 5.0_wp]) < &
                                           1.0e-12_wp), 'MAX edges values')
      opts%interval = 1.0e-3_wp
      opts%has_max = .false.
      call contour_levels(0.0_wp, 10.0_wp, opts, edges, interval)
      call check(size(edges) - 1 <= 20, 'at most 20 bands')
      ! a linear field f = 2x + 3y on a triangle: every band polygon vertex is
      ! a triangle vertex inside the band or lies on an iso-line of its band
      ! edges (tolerance 1e-12, round-off of the edge interpolation), and the
      ! band areas add up to the triangle's area
      x = [0.0_wp, 2.0_wp, 0.3_wp]
      y = [0.0_wp, 0.5_wp, 1.7_wp]
      f = 2.0_wp*x + 3.0_wp*y
      total = 0.0_wp
      do k = -1, 8
         call clip_band(x, y, f, real(k, wp), real(k + 1, wp), px, py, n)
         if (n < 3) cycle
         area = 0.0_wp
         do i = 1, n
            area = area + 0.5_wp*(px(i)*py(modulo(i, n) + 1) - px(modulo(i, n) + 1)*py(i))
            on_level = abs(2.0_wp*px(i) + 3.0_wp*py(i) - real(k, wp)) < 1.0e-12_wp .or. &
                       abs(2.0_wp*px(i) + 3.0_wp*py(i) - real(k + 1, wp)) < 1.0e-12_wp .or. &
                       any(abs(px(i) - x) + abs(py(i) - y) < 1.0e-14_wp)
            call check(on_level, 'band vertex on its iso-line or a triangle vertex')
            call check(2.0_wp*px(i) + 3.0_wp*py(i) >= real(k, wp) - 1.0e-12_wp .and. &
                       2.0_wp*px(i) + 3.0_wp*py(i) <= real(k + 1, wp) + 1.0e-12_wp, &
                       'band vertex value inside the band')
         end do
         call check(area > 0.0_wp, 'band polygon counter-clockwise')
         total = total + area
      end do
      call check_close(total, 0.5_wp*((x(2) - x(1))*(y(3) - y(1)) - (x(3) - x(1))*(y(2) - y(1))), &
                       1.0e-12_wp, 'bands partition the triangle')
      ! zone_field: the displacement field is the gridpoint values; a uniform
      ! zone value averages to itself at every gridpoint
      call zone_field(session%model, 'XDISPLACEMENT', gval)
      call check_close(gval(gc), 5.0_wp, 0.0_wp, 'XDIS field at the centre')
      allocate (zval(session%model%geometry%zones%n))
      zval = 7.0_wp
      call gridpoint_average(session%model%geometry, zval, gval)
      call check(all(abs(gval(1:5) - 7.0_wp) < 1.0e-12_wp), 'nodal average of a uniform value')
      ! SXX nodal value at the centre: mean of -3, -3, -3 and 2 (equal areas)
      call zone_field(session%model, 'SXX', gval)
      call check_close(gval(gc), -7.0_wp/4.0_wp, 1.0e-12_wp, 'SXX nodal average at the centre')
   end subroutine test_contours

   subroutine test_plots()
      integer :: k, before, nfill, npoly, ntext, u, ios
      character(len=200) :: first, last, line
      integer :: gs_status
      logical :: exists
      before = session%nerrors
      do k = 1, size(plot_zone_layer_names)
         call run('PLOT BLOCKS '//trim(plot_zone_layer_names(k)))
         call check(index(session%plot%scene%what, trim(plot_zone_layer_names(k))) > 0, &
                    'zone layer plotted: '//trim(plot_zone_layer_names(k)))
         call check(count_containing('not yet implemented') == 0, &
                    'zone layer implemented: '//trim(plot_zone_layer_names(k)))
      end do
      call check_equal(session%nerrors, before, 'all zone layers plot without error')
      call run('PLOT SXX')
      nfill = count_kind(item_fill)
      call check(nfill >= 4, 'SXX bands are filled polygons')
      ! issue 24: a colour bar, one band per interval, under the title with
      ! the quantity's name and unit
      call check(count_legend(legend_bar) >= 4, 'SXX: a colour bar of bands in the legend')
      call check(any_legend_contains('SXX contours (Pa)'), 'SXX: the bar is titled with its unit')
      call run('PLOT SXX LINE')
      call check(count_kind(item_fill) == 0, 'SXX LINE: no filled bands')
      call check(count_kind(item_polyline) > 0, 'SXX LINE: contour lines')
      ! several contour keywords on one PLOT (manual 4.6: "several variables
      ! may be plotted at once"): filled bands would hide each other, so only
      ! the first is filled, the others are drawn as lines
      call run('PLOT SXX SYY SMIN')
      call check_equal(count_kind(item_fill), nfill, 'PLOT SXX SYY SMIN: only SXX is filled')
      call check(count_legend(legend_line) > 0, 'PLOT SXX SYY SMIN: SYY and SMIN as lines')
      call check(legend_has('lines'), 'PLOT SXX SYY SMIN: the legend says they are lines')
      ! HOEK without UCS / HBM (material 1 has COH FRIC TENS only): F = 0
      ! everywhere, and the legend says why; MOHR has its properties
      call run('PLOT HOEK')
      call check(any_legend_contains('UCS / HBM not given'), 'PLOT HOEK: missing UCS noted')
      call run('PLOT MOHR')
      call check(.not. any_legend_contains('not given'), 'PLOT MOHR: properties given, no note')
      ! TENSION with a filled contour: no pink zones under or over the bands,
      ! its SMAX = 0 line drawn after them (on top)
      call run('PLOT TENSION SXX')
      call check_equal(count_kind(item_fill), nfill, 'PLOT TENSION SXX: only the SXX bands filled')
      call check(last_polyline_red(), 'PLOT TENSION SXX: the SMAX = 0 line is on top')
      ! a legend too long for the panel (here 3 x 20 levels, about 70
      ! entries; 30 fit at full size) is set smaller; no entry is lost
      call run('PLOT SXX INTERVAL 0.01 SDIF INTERVAL 0.01 YDIS INTERVAL 0.01')
      call check(text_drawn('y-displacement contours (m)'), 'long legend: the last title is drawn')
      call check(count_kind(item_text) >= session%plot%scene%nlegend, &
                 'long legend: every entry is drawn')
      ! beyond what fits at the smallest size, a line says what is left out
      call run('PLOT SXX INTERVAL 0.01 SYY INTERVAL 0.01 SDIF INTERVAL 0.01 ' // &
               'XDIS INTERVAL 0.01 YDIS INTERVAL 0.01')
      call check(.not. text_drawn('y-displacement contours (m)'), 'longer legend: cut')
      call check(any_text_contains('more legend entries not shown'), &
                 'longer legend: the cut is reported')
      call run('PLOT XDIS LINE 0 1 2 1 GRID')
      ntext = count_kind(item_text)
      call run('PLOT XDIS LINE GRID')
      call check(ntext > count_kind(item_text), 'LINE x1 y1 x2 y2 labels the contours')
      ! XDIS = 2x + 3y is 0 at (0, 0): ZERO drops the level 0 from the lines
      call run('PLOT XDIS LINE')
      nfill = count_legend(legend_line)
      call run('PLOT XDIS LINE ZERO')
      call check_equal(count_legend(legend_line), nfill - 1, 'ZERO: no zero contour line')
      call run('PLOT XDIS INTERVAL 1 MAX 6 2 ZERO')
      call check_equal(session%nerrors, before, 'switches accepted')
      call run('PLOT SXX MAX 0 1')
      call check_equal(session%nerrors, before + 1, 'MAX vmax <= vmin is an error')
      call run('PLOT GRID')
      call check_equal(session%nerrors, before + 2, 'a switch without a keyword is an error')
      call run('PLOT BLOCKS GRID')
      call check(count_containing('ignored') == 1, 'a switch after a non-contour keyword: note')
      call run('PLOT PLASTICITY')
      npoly = count_kind(item_fill)
      ! one disc for the zone at failure + its legend swatch
      call check_equal(npoly, 2, 'PLASTICITY: a filled disc for the zone at failure')
      call run('PLOT VEL')
      ! the rigid block's centroid is at rest; vy = y moves 3 of the 5
      ! gridpoints ((0,2), (2,2), the centre): each arrow is a shaft and a
      ! filled head
      ! + the legend's scale arrow
      call check(count_kind(item_fill) == 4, 'VEL: arrows at the 3 moving gridpoints')
      ! files: PostScript that ghostscript accepts, and a PNG
      call run('PLOT BLOCKS SMIN GRID STRESSES ZONES')
      call run('COPY zone_output_test.ps')
      call run('COPY zone_output_test.png')
      inquire (file='zone_output_test.png', exist=exists)
      call check(exists, 'PNG written')
      open (newunit=u, file='zone_output_test.ps', status='old', action='read', iostat=ios)
      call check(ios == 0, 'PostScript written')
      if (ios == 0) then
         read (u, '(a)') first
         last = ''
         do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            last = line
         end do
         close (u)
         call check(first(1:10) == '%!PS-Adobe', 'PostScript header')
         call check(trim(last) == '%%EOF', 'PostScript trailer')
         call execute_command_line('command -v gs > /dev/null 2>&1 && (gs -dNOPAUSE -dBATCH ' // &
                                   '-dSAFER -sDEVICE=nullpage -q zone_output_test.ps > ' // &
                                   'zone_output_gs.txt 2>&1; exit $?) || exit 0', &
                                   exitstat=gs_status)
         call check_equal(gs_status, 0, 'ghostscript accepts the PostScript (when installed)')
      end if
      call execute_command_line('rm -f zone_output_test.ps zone_output_test.png ' // &
                                'zone_output_gs.txt')
   end subroutine test_plots

   integer function count_kind(kind) result(n)
      integer, intent(in) :: kind
      integer :: i
      n = 0
      do i = 1, session%plot%scene%nitem
         if (session%plot%scene%items(i)%kind == kind) n = n + 1
      end do
   end function count_kind

   integer function count_legend(kind) result(n)
      integer, intent(in) :: kind
      integer :: i
      n = 0
      do i = 1, session%plot%scene%nlegend
         if (session%plot%scene%legend(i)%kind == kind) n = n + 1
      end do
   end function count_legend

   !> Whether the scene has a text item `text` (drawn, not just listed).
   logical function text_drawn(text) result(found)
      character(len=*), intent(in) :: text
      integer :: i
      found = .false.
      do i = 1, session%plot%scene%nitem
         if (session%plot%scene%items(i)%kind /= item_text) cycle
         if (session%plot%scene%items(i)%text == text) found = .true.
      end do
   end function text_drawn

   !> Whether the last polyline drawn in the plotting area is red (the
   !> SMAX = 0 line of TENSION; the legend items come after it).
   logical function last_polyline_red() result(red_last)
      integer :: i
      red_last = .false.
      do i = 1, session%plot%scene%nitem
         associate (it => session%plot%scene%items(i))
            if (it%kind /= item_polyline .or. .not. it%clip) cycle
            red_last = it%colour(1) > 0.8_wp .and. it%colour(2) < 0.3_wp .and. &
                       it%colour(3) < 0.3_wp
         end associate
      end do
   end function last_polyline_red

   logical function any_legend_contains(text) result(found)
      character(len=*), intent(in) :: text
      integer :: i
      found = .false.
      do i = 1, session%plot%scene%nlegend
         if (index(session%plot%scene%legend(i)%text, text) > 0) found = .true.
      end do
   end function any_legend_contains

   logical function any_text_contains(text) result(found)
      character(len=*), intent(in) :: text
      integer :: i
      found = .false.
      do i = 1, session%plot%scene%nitem
         if (session%plot%scene%items(i)%kind /= item_text) cycle
         if (index(session%plot%scene%items(i)%text, text) > 0) found = .true.
      end do
   end function any_text_contains

   logical function legend_has(text) result(found)
      character(len=*), intent(in) :: text
      integer :: i
      found = .false.
      do i = 1, session%plot%scene%nlegend
         if (index(session%plot%scene%legend(i)%text, ' '//text//' ') > 0) found = .true.
      end do
   end function legend_has

end program test_zone_output
