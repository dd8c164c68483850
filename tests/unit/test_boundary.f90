!> BOUNDARY and INSITU (commands_boundary, zones_boundary_setup, zones_boundary,
!> model_boundary): free-surface detection, stress-to-force conversion (exact
!> for linear stress), the increment rule of the manual's Note, history
!> values, velocity conditions on FDEF gridpoints, HREAD, INSITU joint forces
!> and zone stresses, the balance of a uniform INSITU with the matching
!> BOUNDARY STRESS, and PRINT BOUNDARY.
!> References are hand integrals stated next to each check; tolerance 1e-12
!> relative (round-off of a few operations) unless said otherwise.
program test_boundary
   use core_kinds, only: wp, ip, i8
   use core_motion, only: stage_args_t
   use core_error, only: error_t
   use model_geometry, only: geometry_t
   use model_zones, only: zones_add_gridpoint, zones_add_zone, vfix_x, vfix_y
   use model_boundary, only: boundary_t, boundary_history_value, boundary_index, &
                             bc_stress, bc_velocity, bc_free, bh_linear, bh_sine, bh_cosine, &
                             bh_constant, bh_table1, boundary_has_traction
   use zones_boundary, only: boundary_cycle_start, boundary_step, boundary_cycle_end, &
                             boundary_traction_force
   use commands_session, only: session_t, session_init, session_execute_line
   use testing_session, only: session_run, lines_contain
   use testing, only: check, check_close, check_equal, check_string, testing_finish
   implicit none

   type(session_t) :: session
   character(len=200), allocatable :: lines(:)
   real(wp), parameter :: tol = 1.0e-12_wp
   real(wp) :: fxh, fyh       !< FXHIS, FYHIS returned by boundary_step

   call test_detection_2x2()
   call test_detection_hole()
   call test_stress_unit_square()
   call test_stress_by_sides()
   call test_stress_linear()
   call test_stress_follower()
   call test_fup_setting()
   call test_increment_rule()
   call test_history_values()
   call test_velocity_rigid_error()
   call test_fdef_velocity_and_stress()
   call test_load_under_velocity()
   call test_viscous_after_velocity_fup()
   call test_hread()
   call test_insitu_joints()
   call test_insitu_zones()
   call test_balance()
   call test_print_boundary()
   call test_corner_walk()
   call test_xhis_yhis()
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

   subroutine fresh()
      type(error_t), allocatable :: error
      call session_init(session, error)
      call check(.not. allocated(error), 'session starts')
      call run('ROUND 0.01')
   end subroutine fresh

   !> 2 x 2 blocks of side 1 in [0,2]^2.
   subroutine assembly_2x2()
      call fresh()
      call run('BLOCK 0,0 0,2 2,2 2,0')
      call run('CRACK -1,1 3,1')
      call run('CRACK 1,-1 1,3')
   end subroutine assembly_2x2

   !> Corner of a live block at (x, y) belonging to the block whose centroid
   !> is nearest (bx, by); 0 if none.
   integer(ip) function corner_at(x, y, bx, by) result(id)
      real(wp), intent(in) :: x, y, bx, by
      integer(ip) :: c, b
      real(wp) :: best, d
      id = 0
      best = huge(1.0_wp)
      associate (g => session%model%geometry)
         do c = 1, g%corners%n
            if (.not. g%corners%live(c)) cycle
            b = g%corners%block(c)
            if (.not. g%blocks%live(b)) cycle
            if (hypot(g%corners%x(c) - x, g%corners%y(c) - y) > 1.0e-9_wp) cycle
            d = hypot(g%blocks%xc(b) - bx, g%blocks%yc(b) - by)
            if (d < best) then
               best = d
               id = c
            end if
         end do
      end associate
   end function corner_at

   subroutine test_detection_2x2()
      integer(ip) :: i, c
      logical :: outer
      call assembly_2x2()
      call run('BOUND XMUL 1.0')
      associate (b => session%model%bound, g => session%model%geometry)
         ! 4 blocks x 3 corners on the outer square; the 4 corners at (1,1) are inside
         call check_equal(int(b%n), 12, '2x2: 12 boundary points')
         outer = .true.
         do i = 1, b%n
            c = b%corner(i)
            if (abs(g%corners%x(c) - 1.0_wp) < 1.0e-9_wp .and. &
                abs(g%corners%y(c) - 1.0_wp) < 1.0e-9_wp) outer = .false.
         end do
         call check(outer, '2x2: the interior corners at (1,1) are not boundary points')
      end associate
   end subroutine test_detection_2x2

   !> 3 x 3 blocks with the middle one deleted: the hole's corners are
   !> boundary when BOUNDARY comes after DELETE, not when it comes before.
   subroutine test_detection_hole()
      call fresh()
      call run('BLOCK 0,0 0,3 3,3 3,0')
      call run('CRACK -1,1 4,1')
      call run('CRACK -1,2 4,2')
      call run('CRACK 1,-1 1,4')
      call run('CRACK 2,-1 2,4')
      call run('DELETE 1.4,1.6 1.4,1.6')
      call run('BOUND XMUL 1.0')
      ! outer: 4 corner blocks x 3 + 4 edge-middle blocks x 2 = 20; the hole:
      ! the 4 edge-middle blocks share an edge with it (2 corners each = 8);
      ! the corner blocks touch it at one point only (both edges there are
      ! covered), so their corners there are not boundary points
      call check_equal(int(session%model%bound%n), 28, 'hole: 20 outer + 8 hole points')
      call check(boundary_index(session%model%bound, corner_at(1.0_wp, 1.0_wp, 1.5_wp, 0.5_wp)) &
                 > 0, 'hole: corner (1,1) of the bottom-middle block is a boundary point')
      call check(boundary_index(session%model%bound, corner_at(1.0_wp, 1.0_wp, 0.5_wp, 0.5_wp)) &
                 == 0, 'hole: corner (1,1) of the lower-left block touches it at a point only')

      call fresh()
      call run('BLOCK 0,0 0,3 3,3 3,0')
      call run('CRACK -1,1 4,1')
      call run('CRACK -1,2 4,2')
      call run('CRACK 1,-1 1,4')
      call run('CRACK 2,-1 2,4')
      call run('BOUND XMUL 1.0')
      call check_equal(int(session%model%bound%n), 20, 'before DELETE: 20 outer points')
      call run('DELETE 1.4,1.6 1.4,1.6')
      call run('BOUND XMUL 1.0')
      call check_equal(int(session%model%bound%n), 20, &
                       'hole made after the first BOUNDARY does not join the boundary')
   end subroutine test_detection_hole

   !> Unit square, uniform stress: corner (0,0) gets half of the left side
   !> (n = (-1,0)) and half of the bottom (n = (0,-1)):
   !> f = 0.5 (-sxx, -sxy) + 0.5 (-sxy, -syy); forces sum to zero; each side's
   !> two halves sum to sigma.n times its length.
   !> A stress given side by side (four BOUNDARY lines with ranges, as the
   !> manual's verification C gives its bottom and sides) must load every
   !> point exactly as one BOUNDARY STRESS on the whole boundary: a line acts
   !> on the segments inside its range, so a model corner takes its bottom
   !> half edge from the bottom line and its side half edge from the side
   !> line (before, each line loaded both half edges and corners got twice
   !> the load). Reference: the whole-boundary run; tolerance 1e-12.
   subroutine test_stress_by_sides()
      real(wp), allocatable :: fx(:), fy(:)
      integer(ip) :: n
      call fresh()
      call run('SET -FUP')     ! the fixed forces; FUP tractions: test_stress_follower
      call run('BLOCK 0,0 0,2 2,2 2,0')
      call run('GEN QUAD 0.5')
      call run('BOUND STRESS -1 -0.5 -2')
      n = session%model%bound%n
      fx = session%model%bound%dfx(1:n)
      fy = session%model%bound%dfy(1:n)
      call fresh()
      call run('SET -FUP')     ! the fixed forces; FUP tractions: test_stress_follower
      call run('BLOCK 0,0 0,2 2,2 2,0')
      call run('GEN QUAD 0.5')
      call run('BOUND -0.1 2.1 -0.1 0.1 STRESS -1 -0.5 -2')
      call run('BOUND -0.1 2.1 1.9 2.1 STRESS -1 -0.5 -2')
      call run('BOUND -0.1 0.1 -0.1 2.1 STRESS -1 -0.5 -2')
      call run('BOUND 1.9 2.1 -0.1 2.1 STRESS -1 -0.5 -2')
      call check_equal(int(session%model%bound%n), int(n), 'by sides: same boundary points')
      if (session%model%bound%n /= n) return
      call check(maxval(abs(session%model%bound%dfx(1:n) - fx)) <= tol .and. &
                 maxval(abs(session%model%bound%dfy(1:n) - fy)) <= tol, &
                 'by sides: every point loaded as by the whole-boundary STRESS')
      ! one isolated point still takes its free half edges (0.5 x 0.25 + 0.25 x ...)
      call fresh()
      call run('SET -FUP')     ! the fixed forces; FUP tractions: test_stress_follower
      call run('BLOCK 0,0 0,2 2,2 2,0')
      call run('GEN QUAD 0.5')
      call run('BOUND 0.9 1.1 -0.1 0.1 STRESS 0 0 -2')
      n = session%model%bound%n
      call check_close(sum(session%model%bound%dfy(1:n)), 2.0_wp*0.5_wp, tol, &
                       'isolated point: syy over its two half edges (2 x 0.5)')
   end subroutine test_stress_by_sides

   subroutine test_stress_unit_square()
      real(wp), parameter :: sxx = -2.0_wp, sxy = 0.7_wp, syy = -5.0_wp
      integer(ip) :: i, c00, c01
      call fresh()
      call run('SET -FUP')     ! the fixed forces; FUP tractions: test_stress_follower
      call run('BLOCK 0,0 0,1 1,1 1,0')
      call run('BOUND STRESS -2.0 0.7 -5.0')
      associate (b => session%model%bound)
         call check_equal(int(b%n), 4, 'square: 4 boundary points')
         c00 = corner_at(0.0_wp, 0.0_wp, 0.5_wp, 0.5_wp)
         c01 = corner_at(0.0_wp, 1.0_wp, 0.5_wp, 0.5_wp)
         i = boundary_index(b, c00)
         call check_close(b%dfx(i), -0.5_wp*sxx - 0.5_wp*sxy, tol, 'square: fx at (0,0)')
         call check_close(b%dfy(i), -0.5_wp*sxy - 0.5_wp*syy, tol, 'square: fy at (0,0)')
         call check(b%ix(i) == bc_stress .and. b%iy(i) == bc_stress, 'square: codes 1 1')
         ! left side x = 0: corners (0,0) and (0,1) share it; top side of (0,1): n = (0,1)
         i = boundary_index(b, c01)
         call check_close(b%dfx(i), -0.5_wp*sxx + 0.5_wp*sxy, tol, 'square: fx at (0,1)')
         call check_close(b%dfy(i), -0.5_wp*sxy + 0.5_wp*syy, tol, 'square: fy at (0,1)')
         call check_close(sum(b%dfx(1:b%n)), 0.0_wp, tol, 'square: net fx = 0')
         call check_close(sum(b%dfy(1:b%n)), 0.0_wp, tol, 'square: net fy = 0')
         call check_close(sum(b%fx(1:b%n)), 0.0_wp, 0.0_wp, 'square: totals untouched')
      end associate
   end subroutine test_stress_unit_square

   !> SET FUP (the default): BOUNDARY STRESS is kept as tractions and the
   !> force of a point comes from the edges as they are now. References:
   !> unrotated, the fixed-force values of test_stress_unit_square (exact);
   !> rotated by theta about the centre, each force is sigma times the
   !> point's share of L n turned by theta (the stress stays, the edges
   !> turn), and the forces add up to zero force and zero moment; the same forces held
   !> fixed at the turned corners have the moment cos(theta) sum r x f -
   !> sin(theta) sum r . f = -sin(theta) (sxx + syy) A (sum r . f over the
   !> boundary = trace(sigma) A, sum r x f = 0): the turning moment of dead
   !> loads. Two blocks across a joint mouth: the gap segment is loaded, so
   !> the forces still add up to zero force and moment after one block slides
   !> 0.01 along the joint and opens 0.002. Tolerance 1e-12.
   subroutine test_stress_follower()
      real(wp), parameter :: sxx = -2.0_wp, sxy = 0.7_wp, syy = -5.0_wp, theta = 0.3_wp
      real(wp), parameter :: det = sxx*syy - sxy*sxy
      real(wp) :: fx, fy, dfx, dfy, f0x(4), f0y(4), sx, sy, sm, smd, xr, yr, vx, vy, wx, wy
      integer(ip) :: i, c, c00, b2
      call fresh()
      call run('BLOCK 0,0 0,1 1,1 1,0')
      call run('BOUND STRESS -2.0 0.7 -5.0')
      associate (b => session%model%bound, geo => session%model%geometry)
         call check(b%fup, 'follower: FUP is the default')
         call check_close(sum(abs(b%dfx(1:b%n))) + sum(abs(b%dfy(1:b%n))), 0.0_wp, 0.0_wp, &
                          'follower: no fixed force stored')
         c00 = corner_at(0.0_wp, 0.0_wp, 0.5_wp, 0.5_wp)
         i = boundary_index(b, c00)
         call boundary_traction_force(b, geo, i, fx, fy, dfx, dfy)
         call check_close(dfx, -0.5_wp*sxx - 0.5_wp*sxy, tol, 'follower: fx at (0,0) as fixed')
         call check_close(dfy, -0.5_wp*sxy - 0.5_wp*syy, tol, 'follower: fy at (0,0) as fixed')
         call check_close(fx, 0.0_wp, 0.0_wp, 'follower: no total before a CYCLE')
         do i = 1, b%n
            call boundary_traction_force(b, geo, i, fx, fy, f0x(i), f0y(i))
         end do
         ! turn the block by theta about (0.5, 0.5)
         do i = 1, b%n
            c = b%corner(i)
            xr = geo%corners%x(c) - 0.5_wp
            yr = geo%corners%y(c) - 0.5_wp
            geo%corners%x(c) = 0.5_wp + cos(theta)*xr - sin(theta)*yr
            geo%corners%y(c) = 0.5_wp + sin(theta)*xr + cos(theta)*yr
         end do
         sx = 0.0_wp; sy = 0.0_wp; sm = 0.0_wp; smd = 0.0_wp
         do i = 1, b%n
            c = b%corner(i)
            call boundary_traction_force(b, geo, i, fx, fy, dfx, dfy)
            ! v = sigma^-1 f0 (the point's share of L n), turned: sigma R v
            vx = (syy*f0x(i) - sxy*f0y(i))/det
            vy = (-sxy*f0x(i) + sxx*f0y(i))/det
            wx = cos(theta)*vx - sin(theta)*vy
            wy = sin(theta)*vx + cos(theta)*vy
            call check_close(dfx, sxx*wx + sxy*wy, tol, 'follower: sigma . (turned L n / 2) (x)')
            call check_close(dfy, sxy*wx + syy*wy, tol, 'follower: sigma . (turned L n / 2) (y)')
            sx = sx + dfx
            sy = sy + dfy
            sm = sm + (geo%corners%x(c) - 0.5_wp)*dfy - (geo%corners%y(c) - 0.5_wp)*dfx
            smd = smd + (geo%corners%x(c) - 0.5_wp)*f0y(i) - (geo%corners%y(c) - 0.5_wp)*f0x(i)
         end do
         call check_close(sx, 0.0_wp, tol, 'follower, turned: net fx = 0')
         call check_close(sy, 0.0_wp, tol, 'follower, turned: net fy = 0')
         call check_close(sm, 0.0_wp, tol, 'follower, turned: net moment = 0')
         call check_close(smd, -sin(theta)*(sxx + syy), tol, &
                          'dead loads, turned: moment -sin(theta) trace(sigma) A')
      end associate
      ! two blocks, a joint at x = 1 reaching the top and bottom boundaries
      call fresh()
      call run('BLOCK 0,0 0,1 2,1 2,0')
      call run('CRACK 1,-1 1,2')
      call run('BOUND STRESS -2.0 0.7 -5.0')
      associate (b => session%model%bound, geo => session%model%geometry)
         call check_equal(count(b%end_prev(1:b%n) > 0) + count(b%end_next(1:b%n) > 0), 4, &
                          'mouths: 4 gap segments (2 mouths, both sides)')
         ! slide the right block 0.01 along the joint (y) and open it by 0.002
         b2 = geo%corners%block(corner_at(2.0_wp, 0.0_wp, 1.5_wp, 0.5_wp))
         c = geo%blocks%first_corner(b2)
         do i = 1, geo%blocks%ncorner(b2)
            geo%corners%x(c) = geo%corners%x(c) + 0.002_wp
            geo%corners%y(c) = geo%corners%y(c) + 0.01_wp
            c = geo%corners%next(c)
         end do
         sx = 0.0_wp; sy = 0.0_wp; sm = 0.0_wp
         do i = 1, b%n
            c = b%corner(i)
            call boundary_traction_force(b, geo, i, fx, fy, dfx, dfy)
            sx = sx + dfx
            sy = sy + dfy
            sm = sm + (geo%corners%x(c) - 1.0_wp)*dfy - (geo%corners%y(c) - 0.5_wp)*dfx
         end do
         call check_close(sx, 0.0_wp, tol, 'mouths, slid: net fx = 0')
         call check_close(sy, 0.0_wp, tol, 'mouths, slid: net fy = 0')
         call check_close(sm, 0.0_wp, tol, 'mouths, slid: net moment = 0')
      end associate
   end subroutine test_stress_follower

   !> SET FUP / -FUP: PRINT STATUS names the setting; -FUP turns the
   !> tractions given so far into fixed forces (the values of
   !> test_stress_unit_square, exact) and says so; a line with both is
   !> refused and changes nothing; XFREE on a traction point fixes its
   !> tractions first and frees x only.
   subroutine test_fup_setting()
      integer(ip) :: i
      call fresh()
      call run('PRINT STATUS')
      call check(printed('FUP: tractions on the current boundary (default)'), &
                 'PRINT STATUS: FUP by default')
      call run('BLOCK 0,0 0,1 1,1 1,0')
      call run('BOUND STRESS -2.0 0.7 -5.0')
      call run('SET FUP -FUP')
      call check(printed('*** Error') .and. printed('FUP'), 'SET FUP -FUP: refused')
      call check(session%model%bound%fup, 'SET FUP -FUP: FUP unchanged')
      call run('SET -FUP')
      call check(printed('SET -FUP: the boundary stresses of 4 boundary point(s) are now fixed'), &
                 'SET -FUP: says it fixed the tractions')
      call check(.not. session%model%bound%fup, 'SET -FUP: flag off')
      call run('PRINT STATUS')
      call check(printed('-FUP: fixed forces'), 'PRINT STATUS: -FUP')
      associate (b => session%model%bound)
         i = boundary_index(b, corner_at(0.0_wp, 0.0_wp, 0.5_wp, 0.5_wp))
         call check_close(b%dfx(i), 1.0_wp - 0.35_wp, tol, 'SET -FUP: fixed fx at (0,0)')
         call check_close(b%dfy(i), -0.35_wp + 2.5_wp, tol, 'SET -FUP: fixed fy at (0,0)')
         call check_close(b%dsxx_next(i) + b%dsyy_prev(i), 0.0_wp, 0.0_wp, &
                          'SET -FUP: tractions cleared')
      end associate
      call run('SET FUP')
      call check(session%model%bound%fup, 'SET FUP: flag on')
      call run('BOUND -0.1 0.1 -0.1 0.1 STRESS 0 0 -2')
      call run('BOUND -0.1 0.1 -0.1 0.1 XFREE')
      associate (b => session%model%bound)
         i = boundary_index(b, corner_at(0.0_wp, 0.0_wp, 0.5_wp, 0.5_wp))
         call check_close(b%dfx(i), 0.0_wp, 0.0_wp, 'XFREE on a traction point: x freed')
         ! 2.15 from the first line, + 0.5 x 2 (syy = -2 on the bottom half edge; the
         ! lone selected point takes both its half edges, the left one gives no y)
         call check_close(b%dfy(i), 2.15_wp + 1.0_wp, tol, &
                          'XFREE on a traction point: y kept, fixed')
      end associate
   end subroutine test_fup_setting

   !> Square [0,2]^2 with sxx = s0 + a x + b y, sxy = c + d x + e y,
   !> syy = f + g x + h y (XGRAD a d g, YGRAD b e h). Corner (0,0) takes the
   !> consistent share (hat function 1 - s/2) of each edge of length 2:
   !> left edge, n = (-1,0): fx = -int (1 - y/2) sxx(0,y) = -(s0 + 2b/3),
   !> fy = -(c + 2e/3); bottom edge, n = (0,-1): fx = -(c + 2d/3),
   !> fy = -(f + 2g/3) (the traction at the edge's third point times 1).
   !> Net force = area * div(sigma) = 4 (a + e, d + h).
   subroutine test_stress_linear()
      real(wp), parameter :: s0 = -1.0_wp, a = 0.3_wp, bb = -0.4_wp, c = 0.2_wp, &
                             d = 0.11_wp, e = -0.07_wp, f = -3.0_wp, g = 0.05_wp, h = 0.9_wp
      real(wp), parameter :: fx0 = -(s0 + 2.0_wp*bb/3.0_wp) - (c + 2.0_wp*d/3.0_wp), &
                             fy0 = -(c + 2.0_wp*e/3.0_wp) - (f + 2.0_wp*g/3.0_wp)
      integer(ip) :: i
      call fresh()
      call run('SET -FUP')     ! the fixed forces; FUP tractions: test_stress_follower
      call run('BLOCK 0,0 0,2 2,2 2,0')
      call run('BOUND STRESS -1.0 0.2 -3.0 XGRAD 0.3 0.11 0.05 YGRAD -0.4 -0.07 0.9')
      call check_square('linear', fx0, fy0, 4.0_wp*(a + e), 4.0_wp*(d + h))
      ! LSTRESS: the same nine numbers in one keyword
      call fresh()
      call run('SET -FUP')     ! the fixed forces; FUP tractions: test_stress_follower
      call run('BLOCK 0,0 0,2 2,2 2,0')
      call run('BOUND LSTRESS -1.0 0.2 -3.0 0.3 0.11 0.05 -0.4 -0.07 0.9')
      associate (b => session%model%bound)
         i = boundary_index(b, corner_at(0.0_wp, 0.0_wp, 1.0_wp, 1.0_wp))
         call check_close(b%dfx(i), fx0, tol, 'LSTRESS: fx at (0,0)')
      end associate
      call run('BOUND XGRAD 1 2 3')
      call check(printed('*** Error') .and. printed('XGRAD'), 'XGRAD without STRESS is an error')
      ! a zoned block: the corner (0,0) is a gridpoint and takes the same consistent
      ! force (until session 41 the half edge's quarter-point integral,
      ! L (3 t_c + t_o) / 8: fx would have been -(s0 + b/2) - (c + d/2))
      call fresh()
      call run('SET -FUP')
      call run('BLOCK 0,0 0,2 2,2 2,0')
      call run('GEN QUAD 2')
      call run('BOUND STRESS -1.0 0.2 -3.0 XGRAD 0.3 0.11 0.05 YGRAD -0.4 -0.07 0.9')
      associate (b => session%model%bound, geo => session%model%geometry)
         i = boundary_index(b, corner_at(0.0_wp, 0.0_wp, 1.0_wp, 1.0_wp))
         call check(geo%corners%gp(b%corner(i)) /= 0, 'zoned: (0,0) is a gridpoint')
      end associate
      call check_square('zoned', fx0, fy0, 4.0_wp*(a + e), 4.0_wp*(d + h))
   end subroutine test_stress_linear

   !> test_stress_linear's square: the force at the corner (0,0) and the net
   !> force of the boundary against the expected values.
   subroutine check_square(label, fx0, fy0, netx, nety)
      character(*), intent(in) :: label
      real(wp), intent(in) :: fx0, fy0, netx, nety
      integer(ip) :: i
      associate (b => session%model%bound)
         i = boundary_index(b, corner_at(0.0_wp, 0.0_wp, 1.0_wp, 1.0_wp))
         call check_close(b%dfx(i), fx0, tol, label//': fx at (0,0)')
         call check_close(b%dfy(i), fy0, tol, label//': fy at (0,0)')
         call check_close(sum(b%dfx(1:b%n)), netx, tol, label//': net fx = A div')
         call check_close(sum(b%dfy(1:b%n)), nety, tol, label//': net fy = A div')
      end associate
   end subroutine check_square

   !> Manual Note: loads given before a CYCLE are an increment; applied during
   !> the CYCLE times the history value; added into the totals at its end.
   subroutine test_increment_rule()
      integer(ip) :: i, b1
      real(wp) :: f1
      call fresh()
      call run('BLOCK 0,0 0,1 1,1 1,0')
      call run('BOUND XLOAD 3.0')
      associate (b => session%model%bound, g => session%model%geometry)
         call check_close(sum(b%dfx(1:b%n)), 12.0_wp, tol, 'XLOAD: increment 4 x 3')
         call check_close(sum(b%fx(1:b%n)), 0.0_wp, 0.0_wp, 'XLOAD: totals still 0')
         ! step 5 of 10 with LINEAR: the block gets total + increment * 0.5
         call run('BOUND XHIST LINEAR')
         b1 = g%corners%block(b%corner(1))
         g%blocks%fx(b1) = 0.0_wp
         g%blocks%fy(b1) = 0.0_wp
         g%blocks%fm(b1) = 0.0_wp
         call boundary_cycle_start(b, g, stage_args_t(time=0.0_wp, ncycles=10_i8))
         call boundary_step(b, g, stage_args_t(time=0.5_wp, k=5_i8, ncycles=10_i8), fxh, fyh)
         call check_close(g%blocks%fx(b1), 6.0_wp, tol, 'LINEAR at k = 5 of 10: 12 * 0.5')
         ! FXHIS (HISTORY XHIS) is the LINEAR value k / ncycles; no y history: 1
         call check_close(fxh, 0.5_wp, tol, 'XHIS: LINEAR at k = 5 of 10')
         call check_close(fyh, 1.0_wp, 0.0_wp, 'YHIS: CONSTANT reads 1')
         ! the four loads at the corners of a square about its centroid: no moment
         call check_close(g%blocks%fm(b1), 0.0_wp, tol, 'XLOAD: no moment')
         call boundary_cycle_end(b)
         call check_close(sum(b%fx(1:b%n)), 12.0_wp, tol, 'after the CYCLE: totals 12')
         call check_close(sum(b%dfx(1:b%n)), 0.0_wp, 0.0_wp, 'after the CYCLE: increment 0')
         call check(all(b%hx(1:b%n) == bh_constant), 'after the CYCLE: history CONSTANT')
      end associate
      ! a second load after cycling: increment again, folded by the next end
      session%model%cycled = .true.
      call run('BOUND XLOAD 1.0')
      associate (b => session%model%bound, g => session%model%geometry)
         i = 1
         call check_close(b%dfx(i), 1.0_wp, tol, 'load after a CYCLE: increment')
         call check_close(b%fx(i), 3.0_wp, tol, 'load after a CYCLE: total unchanged')
         b1 = g%corners%block(b%corner(1))
         g%blocks%fx(b1) = 0.0_wp
         call boundary_step(b, g, stage_args_t(time=0.1_wp, k=1_i8, ncycles=10_i8), fxh, fyh)
         call check_close(g%blocks%fx(b1), 16.0_wp, tol, 'CONSTANT: total 12 + increment 4')
         call boundary_cycle_end(b)
         f1 = sum(b%fx(1:b%n))
         call check_close(f1, 16.0_wp, tol, 'second CYCLE end: totals 16')
      end associate
      ! multiplier scales the applied force
      call run('BOUND XMUL 0.5')
      associate (b => session%model%bound, g => session%model%geometry)
         b1 = g%corners%block(b%corner(1))
         g%blocks%fx(b1) = 0.0_wp
         call boundary_step(b, g, stage_args_t(time=0.1_wp, k=1_i8, ncycles=10_i8), fxh, fyh)
         call check_close(g%blocks%fx(b1), 8.0_wp, tol, 'XMUL 0.5: half of 16')
      end associate
      ! XFREE removes the condition
      call run('BOUND XFREE')
      associate (b => session%model%bound)
         call check(all(b%ix(1:b%n) == bc_free), 'XFREE: code 0')
         call check_close(sum(abs(b%fx(1:b%n))), 0.0_wp, 0.0_wp, 'XFREE: no force')
      end associate
   end subroutine test_increment_rule

   subroutine test_history_values()
      type(boundary_t) :: b
      real(wp), parameter :: pi = 3.14159265358979323846_wp
      b%t_start = 2.0_wp
      ! LINEAR: k / n
      call check_close(boundary_history_value(b, bh_linear, 0.0_wp, 0.0_wp, 9.0_wp, 3_i8, 12_i8), &
                       0.25_wp, tol, 'LINEAR: 3 of 12')
      ! SINE f = 2, tload 1, from the CYCLE start 2.0: at 2.1, sin(2 pi 2 0.1)
      call check_close(boundary_history_value(b, bh_sine, 2.0_wp, 1.0_wp, 2.1_wp, 1_i8, 5_i8), &
                       sin(2.0_wp*pi*0.2_wp), tol, 'SINE: value at 0.1 s into the CYCLE')
      call check_close(boundary_history_value(b, bh_sine, 2.0_wp, 1.0_wp, 3.5_wp, 1_i8, 5_i8), &
                       0.0_wp, 0.0_wp, 'SINE: 0 after tload')
      call check_close(boundary_history_value(b, bh_cosine, 2.0_wp, 1.0_wp, 2.0_wp, 1_i8, 5_i8), &
                       1.0_wp, tol, 'COSINE: 1 at the start')
      ! table 1: values 0 10 20 at dt 0.5; at t = 0.75: 15; beyond 1.0: 0
      b%table(1)%np = 3
      b%table(1)%dt = 0.5_wp
      b%table(1)%values = [0.0_wp, 10.0_wp, 20.0_wp]
      call check_close(boundary_history_value(b, bh_table1, 0.0_wp, 0.0_wp, 0.75_wp, 1_i8, 5_i8), &
                       15.0_wp, tol, 'table: linear interpolation')
      call check_close(boundary_history_value(b, bh_table1, 0.0_wp, 0.0_wp, 1.0_wp, 1_i8, 5_i8), &
                       20.0_wp, tol, 'table: last value')
      call check_close(boundary_history_value(b, bh_table1, 0.0_wp, 0.0_wp, 1.2_wp, 1_i8, 5_i8), &
                       0.0_wp, 0.0_wp, 'table: 0 beyond the last value')
   end subroutine test_history_values

   subroutine test_velocity_rigid_error()
      integer :: nerr
      ! XVEL / YVEL on rigid corners constrain their blocks (issue 22:
      ! engine_rigid_velocity, tests/unit/test_rigid_velocity.f90); it used
      ! to be refused
      call assembly_2x2()
      nerr = session%nerrors
      call run('BOUND XVEL=0 YVEL=0')
      call check(session%nerrors == nerr, 'XVEL on rigid blocks: accepted')
      call check(printed('constrains the motion of their block') .and. printed('corner'), &
                 'XVEL on rigid blocks: a note names the first corner')
      call check_equal(int(session%model%bound%n), 12, 'XVEL on rigid blocks: boundary list built')
      call check(all(session%model%bound%ix(1:12) == 4), 'XVEL on rigid blocks: code 4')
      call run('BOUND STRESS -1 0 -1')
      call check_equal(int(session%model%bound%n), 12, 'STRESS on rigid blocks accepted')
      call check(all(session%model%bound%ix(1:12) == 1), 'STRESS replaces the velocity')
   end subroutine test_velocity_rigid_error

   !> Make the single block of the session an FDEF block zoned by hand: one
   !> gridpoint per corner and one at the centroid, one zone per edge.
   !> HISTORY XHIS / YHIS (manual HISTORY table; FXHIS / FYHIS of Section 6):
   !> the value of the boundary history in each sampled step. Reference:
   !> a y-load with YHIST SINE f t samples sin(2 pi f (t_k - t_start)) with
   !> t_k the sample's time (the load of step k acts at t_k); no x history
   !> reads 1 (CONSTANT); after the CYCLE the history is CONSTANT again.
   subroutine test_xhis_yhis()
      real(wp), parameter :: pi = 3.14159265358979323846_wp, f = 2.0_wp
      integer(ip) :: s
      real(wp) :: t0
      call fresh()
      call run('BLOCK 0,0 0,1 1,1 1,0')
      call run('PROP MAT=1 D=1000 K=1E8 G=1E8')
      call zone_single_block()
      call run('BOUND -0.1,1.1 -0.1,0.1 YVEL 0')
      call run('BOUND -0.1,1.1 0.9,1.1 YLOAD -1E3 YHIST SINE 2.0 10.0')
      call run('HIST NCYC 5 XHIS YHIS')
      call check(any(index(lines, 'history 1: XHIS') > 0), 'HISTORY XHIS: listed as history 1')
      t0 = session%model%mech%time
      call run('CYCLE 40')
      associate (h => session%model%hist)
         call check_equal(int(h%nsample), 8, 'XHIS/YHIS: 40 cycles sampled every 5')
         do s = 1, h%nsample
            call check_close(h%values(1, s), 1.0_wp, 0.0_wp, 'XHIS: no x history reads 1')
            call check_close(h%values(2, s), sin(2.0_wp*pi*f*(h%time(s) - t0)), 1.0e-12_wp, &
                             'YHIS: SINE value at the sample time')
         end do
         call check(maxval(abs(h%values(2, 1:h%nsample))) > 0.0_wp, 'YHIS: not all zero')
      end associate
      call run('CYCLE 5')
      associate (h => session%model%hist)
         call check_close(h%values(2, h%nsample), 1.0_wp, 0.0_wp, &
                          'YHIS: the next CYCLE is CONSTANT again (reads 1)')
      end associate
   end subroutine test_xhis_yhis

   subroutine zone_single_block()
      integer(ip) :: b, c, i, gc, g, z, g0, z0, n
      integer(ip), allocatable :: gps(:)
      associate (geo => session%model%geometry)
         b = 1
         n = geo%blocks%ncorner(b)
         allocate (gps(n))
         g0 = geo%gridpoints%n + 1
         c = geo%blocks%first_corner(b)
         do i = 1, n
            call zones_add_gridpoint(geo%gridpoints, b, c, geo%corners%x(c), geo%corners%y(c), g)
            geo%corners%gp(c) = g
            gps(i) = g
            c = geo%corners%next(c)
         end do
         call zones_add_gridpoint(geo%gridpoints, b, 0_ip, geo%blocks%xc(b), geo%blocks%yc(b), gc)
         z0 = geo%zones%n + 1
         do i = 1, n
            ! corners run clockwise: (centre, next, this) is counter-clockwise
            call zones_add_zone(geo%zones, b, gc, gps(merge(1_ip, i + 1, i == n)), gps(i), z)
         end do
         geo%blocks%fdef(b) = .true.
         geo%blocks%gfirst(b) = g0
         geo%blocks%ngp(b) = n + 1
         geo%blocks%zfirst(b) = z0
         geo%blocks%nzone(b) = n
      end associate
   end subroutine zone_single_block

   subroutine test_fdef_velocity_and_stress()
      integer(ip) :: i, c, g
      call fresh()
      call run('BLOCK 0,0 0,1 1,1 1,0')
      call zone_single_block()
      call run('BOUND -0.1,0.1 -0.1,1.1 XVEL=0.25')
      associate (b => session%model%bound, geo => session%model%geometry)
         call check_equal(int(b%n), 4, 'FDEF square: 4 boundary points')
         c = corner_at(0.0_wp, 0.0_wp, 0.5_wp, 0.5_wp)
         i = boundary_index(b, c)
         g = geo%corners%gp(c)
         call check(b%ix(i) == bc_velocity .and. b%iy(i) == bc_free, 'XVEL: codes 4 0')
         call check(iand(geo%gridpoints%vfix(g), vfix_x) /= 0, 'XVEL: vfix_x set')
         call check(iand(geo%gridpoints%vfix(g), vfix_y) == 0, 'XVEL: vfix_y clear')
         call boundary_cycle_start(b, geo, stage_args_t(time=0.0_wp, ncycles=10_i8))
         call check_close(geo%gridpoints%vx(g), 0.25_wp, tol, 'cycle start: prescribed vx')
         ! the reaction: no applied force enters a velocity direction
         geo%gridpoints%fx(g) = 7.0_wp
         call boundary_step(b, geo, stage_args_t(time=0.0_wp, k=1_i8, ncycles=10_i8), fxh, fyh)
         call check_close(geo%gridpoints%fx(g), 7.0_wp, 0.0_wp, 'velocity direction: fx untouched')
         c = corner_at(1.0_wp, 0.0_wp, 0.5_wp, 0.5_wp)
         call check(b%ix(boundary_index(b, c)) == bc_free, 'XVEL range: x = 1 side untouched')
      end associate
      ! STRESS replaces the velocity (manual Caution)
      call run('BOUND STRESS -1 0 -2')
      associate (b => session%model%bound, geo => session%model%geometry)
         c = corner_at(0.0_wp, 0.0_wp, 0.5_wp, 0.5_wp)
         i = boundary_index(b, c)
         g = geo%corners%gp(c)
         call check(b%ix(i) == bc_stress .and. b%iy(i) == bc_stress, 'STRESS after XVEL: codes 1 1')
         call check(iand(geo%gridpoints%vfix(g), vfix_x) == 0, 'STRESS after XVEL: vfix cleared')
         ! forces go into the gridpoint: (0,0) gets 0.5 (1, 0) + 0.5 (0, 2)
         geo%gridpoints%fx(g) = 0.0_wp
         geo%gridpoints%fy(g) = 0.0_wp
         call boundary_step(b, geo, stage_args_t(time=0.0_wp, k=1_i8, ncycles=10_i8), fxh, fyh)
         call check_close(geo%gridpoints%fx(g), 0.5_wp, tol, 'FDEF: fx at (0,0) into the gridpoint')
         call check_close(geo%gridpoints%fy(g), 1.0_wp, tol, 'FDEF: fy at (0,0) into the gridpoint')
      end associate
   end subroutine test_fdef_velocity_and_stress

   !> A load stays stored when the point later gets a velocity (docs/zones.md
   !> "Loads under a prescribed velocity"): the velocity wins in the step,
   !> the load is kept, a later load adds to it, XFREE brings it back, a
   !> second XFREE removes it. Reference values: the square's STRESS shares
   !> (test above: 0.5 in x and 1.0 in y at (0,0)), exact.
   subroutine test_load_under_velocity()
      integer(ip) :: i, c, g
      call fresh()
      call run('SET -FUP')     ! the fixed forces; FUP tractions: test_stress_follower
      call run('BLOCK 0,0 0,1 1,1 1,0')
      call zone_single_block()
      call run('BOUND STRESS -1 0 -2')
      call run('BOUND -0.1,0.1 -0.1,0.1 XVEL=0 YVEL=0')
      associate (b => session%model%bound, geo => session%model%geometry)
         c = corner_at(0.0_wp, 0.0_wp, 0.5_wp, 0.5_wp)
         i = boundary_index(b, c)
         g = geo%corners%gp(c)
         call check(b%ix(i) == bc_velocity .and. b%iy(i) == bc_velocity, 'held load: codes 4 4')
         call check_close(b%dfx(i), 0.5_wp, tol, 'held load: x increment kept under XVEL')
         call check_close(b%dfy(i), 1.0_wp, tol, 'held load: y increment kept under YVEL')
         ! the velocity wins: nothing enters the gridpoint's force sum
         geo%gridpoints%fx(g) = 0.0_wp
         geo%gridpoints%fy(g) = 0.0_wp
         call boundary_step(b, geo, stage_args_t(time=0.0_wp, k=1_i8, ncycles=10_i8), fxh, fyh)
         call check_close(geo%gridpoints%fx(g), 0.0_wp, 0.0_wp, 'held load: not in the force sum')
         call boundary_cycle_end(b)
         call check_close(b%fx(i), 0.5_wp, tol, 'held load: folded into the total at the CYCLE end')
      end associate
      ! a later load replaces the velocity (manual Caution) and adds to the total
      call run('BOUND -0.1,0.1 -0.1,0.1 XLOAD 2')
      associate (b => session%model%bound)
         c = corner_at(0.0_wp, 0.0_wp, 0.5_wp, 0.5_wp)
         i = boundary_index(b, c)
         call check(b%ix(i) == bc_stress .and. b%iy(i) == bc_velocity, 'XLOAD after XVEL: codes 1 4')
         call check_close(b%fx(i) + b%dfx(i), 2.5_wp, tol, 'XLOAD after XVEL: stored 0.5 + 2')
      end associate
      ! YFREE releases the velocity: the stored y load acts again
      call run('BOUND -0.1,0.1 -0.1,0.1 YFREE')
      associate (b => session%model%bound, geo => session%model%geometry)
         c = corner_at(0.0_wp, 0.0_wp, 0.5_wp, 0.5_wp)
         i = boundary_index(b, c)
         g = geo%corners%gp(c)
         call check(b%iy(i) == bc_stress, 'YFREE after YVEL: code 1 (the stored load acts)')
         call check(iand(geo%gridpoints%vfix(g), vfix_y) == 0, 'YFREE after YVEL: vfix_y cleared')
         call check_close(b%fy(i), 1.0_wp, tol, 'YFREE after YVEL: load kept')
         geo%gridpoints%fy(g) = 0.0_wp
         call boundary_step(b, geo, stage_args_t(time=0.0_wp, k=1_i8, ncycles=10_i8), fxh, fyh)
         call check_close(geo%gridpoints%fy(g), 1.0_wp, tol, 'YFREE after YVEL: the load enters the step')
      end associate
      ! a second YFREE removes the load
      call run('BOUND -0.1,0.1 -0.1,0.1 YFREE')
      associate (b => session%model%bound)
         i = boundary_index(b, corner_at(0.0_wp, 0.0_wp, 0.5_wp, 0.5_wp))
         call check(b%iy(i) == bc_free, 'second YFREE: code 0')
         call check_close(abs(b%fy(i)) + abs(b%dfy(i)), 0.0_wp, 0.0_wp, 'second YFREE: no load')
      end associate
      ! YVISC replacing a velocity: the balancing total -(gp f + m g) acts
      ! times YMUL, so it is stored divided by it (no gravity here): a force
      ! sum of -3 with YMUL 2 gives 1.5, and the force sum balances at once
      call run('BOUND -0.1,0.1 -0.1,0.1 YVEL 0 YMUL 2')
      associate (b => session%model%bound, geo => session%model%geometry)
         c = corner_at(0.0_wp, 0.0_wp, 0.5_wp, 0.5_wp)
         geo%gridpoints%fy(geo%corners%gp(c)) = -3.0_wp
      end associate
      call run('BOUND -0.1,0.1 -0.1,0.1 MAT 1 YVISC')
      associate (b => session%model%bound, geo => session%model%geometry)
         c = corner_at(0.0_wp, 0.0_wp, 0.5_wp, 0.5_wp)
         i = boundary_index(b, c)
         call check_close(b%fy(i), 1.5_wp, tol, 'YVISC after YVEL with YMUL 2: load 3 / 2')
         call check_close(geo%gridpoints%fy(geo%corners%gp(c)), 0.0_wp, tol, &
                          'YVISC after YVEL: force sum balanced')
      end associate
   end subroutine test_load_under_velocity

   !> YVISC replacing a velocity under SET FUP (the default): the point's
   !> STRESS is kept as tractions on its half edges, which the step adds to
   !> the fixed load, so the fixed part becomes the balancing total minus
   !> the traction's force and the step applies the total once (before the
   !> fix the total plus the traction: Application A's top and bottom
   !> carried their in-situ stress twice). Reference: a force sum of -3 at
   !> (0,0) with the square's STRESS share 1.0 in y there: the step applies 3.
   subroutine test_viscous_after_velocity_fup()
      integer(ip) :: i, c, g
      call fresh()
      call run('BLOCK 0,0 0,1 1,1 1,0')
      call zone_single_block()
      call run('BOUND STRESS -1 0 -2')
      call run('BOUND -0.1,0.1 -0.1,0.1 XVEL=0 YVEL=0')
      associate (b => session%model%bound, geo => session%model%geometry)
         call boundary_cycle_end(b)     ! the tractions' increments become totals
         c = corner_at(0.0_wp, 0.0_wp, 0.5_wp, 0.5_wp)
         g = geo%corners%gp(c)
         geo%gridpoints%fy(g) = -3.0_wp
      end associate
      call run('BOUND -0.1,0.1 -0.1,0.1 MAT 1 YVISC')
      associate (b => session%model%bound, geo => session%model%geometry)
         c = corner_at(0.0_wp, 0.0_wp, 0.5_wp, 0.5_wp)
         i = boundary_index(b, c)
         g = geo%corners%gp(c)
         call check(boundary_has_traction(b, i), 'YVISC under FUP: the tractions stay')
         call check_close(b%fy(i), 2.0_wp, tol, 'YVISC under FUP: fixed part 3 - traction 1')
         geo%gridpoints%fy(g) = 0.0_wp
         call boundary_step(b, geo, stage_args_t(time=0.0_wp, k=1_i8, ncycles=10_i8), fxh, fyh)
         call check_close(geo%gridpoints%fy(g), 3.0_wp, tol, &
                          'YVISC under FUP: the step applies the balancing total once')
      end associate
   end subroutine test_viscous_after_velocity_fup

   subroutine test_hread()
      integer :: u, nerr
      call fresh()
      call run('BLOCK 0,0 0,1 1,1 1,0')
      open (newunit=u, file='test_boundary_h1.txt', status='replace', action='write')
      write (u, '(a)') 'TEST HISTORY'
      write (u, '(a)') '4 0.25'
      write (u, '(a)') '0.0 1.0'
      write (u, '(a)') '2.0 3.0'
      close (u)
      call run('BOUND HREAD 1 test_boundary_h1.txt XHIST 1')
      associate (t => session%model%bound%table(1))
         call check_equal(int(t%np), 4, 'HREAD: 4 values')
         call check_close(t%dt, 0.25_wp, 0.0_wp, 'HREAD: tdel')
         if (t%np == 4) call check_close(t%values(4), 3.0_wp, 0.0_wp, 'HREAD: last value')
         call check_string(t%heading, 'TEST HISTORY', 'HREAD: heading')
      end associate
      call check(all(session%model%bound%hx(1:4) == bh_table1), 'XHIST 1: table 1')
      ! malformed: only 3 of 5 values
      open (newunit=u, file='test_boundary_h2.txt', status='replace', action='write')
      write (u, '(a)') 'SHORT'
      write (u, '(a)') '5 0.1'
      write (u, '(a)') '1 2 3'
      close (u)
      nerr = session%nerrors
      call run('BOUND HREAD 2 test_boundary_h2.txt')
      call check(session%nerrors == nerr + 1, 'HREAD short file: an error')
      call check(printed('expected 5 numeric values'), 'HREAD short file: says what is missing')
      call check_equal(int(session%model%bound%table(2)%np), 0, 'HREAD error: table 2 unset')
      call run('BOUND XHIST 2')
      call check(printed('has not been read'), 'XHIST 2 before HREAD 2: an error')
      call run('BOUND HREAD 1 no_such_file_here.txt')
      call check(printed('cannot open'), 'HREAD missing file: an error')
      open (newunit=u, file='test_boundary_h2.txt', status='old')
      close (u, status='delete')
      open (newunit=u, file='test_boundary_h1.txt', status='old')
      close (u, status='delete')
   end subroutine test_hread

   !> Two blocks split at x = 1; INSITU sxx sxy syy = -2, 0.5, -5. Reference:
   !> the force on block2 from block1 is the traction on block2's face, whose
   !> outward normal is -n: F = -sigma.n L; contact_mechanics applies
   !> F = fn n - fs t with t = (-ny, nx). So fn = 2 L (compression positive)
   !> and fn n - fs t must equal -sigma.n L.
   subroutine test_insitu_joints()
      integer(ip) :: c, nc
      real(wp) :: nx, ny, l, fx, fy
      call fresh()
      call run('BLOCK 0,0 0,2 2,2 2,0')
      call run('CRACK 1,-1 1,3')
      call run('PROP MAT=1 JKN=100 JKS=50')
      call run('INSITU STRESS -2.0 0.5 -5.0')
      nc = 0
      associate (ct => session%model%geometry%contacts)
         do c = 1, ct%n
            if (.not. ct%live(c)) cycle
            l = ct%length(c)
            if (l <= 0.0_wp) cycle
            nc = nc + 1
            nx = ct%nx(c)
            ny = ct%ny(c)
            call check_close(ct%state%fn(c), 2.0_wp*l, tol, 'INSITU: fn = -n.sigma.n L > 0')
            fx = ct%state%fn(c)*nx - ct%state%fs(c)*(-ny)
            fy = ct%state%fn(c)*ny - ct%state%fs(c)*nx
            call check_close(fx, -(-2.0_wp*nx + 0.5_wp*ny)*l, tol, 'INSITU: force x on block2')
            call check_close(fy, -(0.5_wp*nx - 5.0_wp*ny)*l, tol, 'INSITU: force y on block2')
            ! JCONS 2 (default): stiffness JKN L, dFn = -Kn dUn
            call check_close(ct%state%un(c), -ct%state%fn(c)/(100.0_wp*l), tol, 'INSITU: un')
            call check_close(ct%state%us(c), ct%state%fs(c)/(50.0_wp*l), tol, 'INSITU: us')
         end do
      end associate
      call check(nc >= 2, 'INSITU: the joint has contacts with length')
      call check(session%model%geometry%mechanical, 'INSITU: contacts now keep their forces')
   end subroutine test_insitu_joints

   !> Zones of a hand-zoned block: stress at the zone centroid, szz = nu (sxx + syy),
   !> nu = (3K - 2G) / (2 (3K + G)) = 0.25 for K = 5, G = 3.
   subroutine test_insitu_zones()
      integer(ip) :: z
      real(wp) :: yc
      call fresh()
      call run('BLOCK 0,0 0,1 1,1 1,0')
      call run('PROP MAT=1 K=5 G=3')
      call zone_single_block()
      call run('INSITU STRESS -1 0 -2 YGRAD 0.5 0 0.25')
      associate (zn => session%model%geometry%zones, gp => session%model%geometry%gridpoints)
         call check_equal(int(zn%n), 4, 'zones: 4 by hand')
         do z = 1, zn%n
            yc = (gp%y(zn%g1(z)) + gp%y(zn%g2(z)) + gp%y(zn%g3(z)))/3.0_wp
            call check_close(zn%sxx(z), -1.0_wp + 0.5_wp*yc, tol, 'zone sxx at its centroid')
            call check_close(zn%syy(z), -2.0_wp + 0.25_wp*yc, tol, 'zone syy at its centroid')
            call check_close(zn%szz(z), 0.25_wp*(zn%sxx(z) + zn%syy(z)), tol, 'zone szz')
         end do
      end associate
      ! the manual's two-value YGRAD: sxyy syyy
      call run('INSITU STRESS -1 0 -2 YGRAD 0.1 0.25')
      associate (zn => session%model%geometry%zones, gp => session%model%geometry%gridpoints)
         yc = (gp%y(zn%g1(1)) + gp%y(zn%g2(1)) + gp%y(zn%g3(1)))/3.0_wp
         call check_close(zn%sxx(1), -1.0_wp, tol, 'YGRAD 2 values: sxx uniform')
         call check_close(zn%sxy(1), 0.1_wp*yc, tol, 'YGRAD 2 values: sxy = sxyy y')
      end associate
   end subroutine test_insitu_zones

   !> Acceptance: a uniform INSITU with the matching BOUNDARY STRESS leaves no
   !> out-of-balance force or moment on any block of a 2 x 2 assembly
   !> (contact forces as contact_mechanics sums them + boundary forces).
   subroutine test_balance()
      integer(ip) :: c, b1, b2, b
      real(wp) :: fx, fy, px, py, scale
      call assembly_2x2()
      call run('PROP MAT=1 JKN=1e3 JKS=1e3')
      call run('INSITU STRESS -2.0E6 0.3E6 -5.0E6')
      call run('BOUND STRESS -2.0E6 0.3E6 -5.0E6')
      scale = 5.0e6_wp
      associate (g => session%model%geometry)
         g%blocks%fx = 0.0_wp
         g%blocks%fy = 0.0_wp
         g%blocks%fm = 0.0_wp
         do c = 1, g%contacts%n
            if (.not. g%contacts%live(c)) cycle
            fx = g%contacts%state%fn(c)*g%contacts%nx(c) + g%contacts%state%fs(c)*g%contacts%ny(c)
            fy = g%contacts%state%fn(c)*g%contacts%ny(c) - g%contacts%state%fs(c)*g%contacts%nx(c)
            b1 = g%contacts%block1(c)
            b2 = g%contacts%block2(c)
            px = g%contacts%x(c)
            py = g%contacts%y(c)
            g%blocks%fx(b2) = g%blocks%fx(b2) + fx
            g%blocks%fy(b2) = g%blocks%fy(b2) + fy
            g%blocks%fm(b2) = g%blocks%fm(b2) + (px - g%blocks%xc(b2))*fy - (py - g%blocks%yc(b2))*fx
            g%blocks%fx(b1) = g%blocks%fx(b1) - fx
            g%blocks%fy(b1) = g%blocks%fy(b1) - fy
            g%blocks%fm(b1) = g%blocks%fm(b1) - ((px - g%blocks%xc(b1))*fy - (py - g%blocks%yc(b1))*fx)
         end do
         call boundary_cycle_start(session%model%bound, g, stage_args_t(time=0.0_wp, ncycles=1_i8))
         call boundary_step(session%model%bound, g, &
            stage_args_t(time=0.0_wp, k=1_i8, ncycles=1_i8), fxh, fyh)
         do b = 1, g%blocks%n
            if (.not. g%blocks%live(b)) cycle
            call check_close(g%blocks%fx(b)/scale, 0.0_wp, 1.0e-12_wp, 'balance: block fx')
            call check_close(g%blocks%fy(b)/scale, 0.0_wp, 1.0e-12_wp, 'balance: block fy')
            call check_close(g%blocks%fm(b)/scale, 0.0_wp, 1.0e-12_wp, 'balance: block moment')
         end do
      end associate
   end subroutine test_balance

   subroutine test_print_boundary()
      call fresh()
      call run('BLOCK 0,0 0,1 1,1 1,0')
      call run('PRINT BOUNDARY')
      call check(printed('no boundary conditions'), 'PRINT BOUNDARY before BOUNDARY')
      call run('BOUND STRESS -2 0 -4')
      call run('PRINT BOUNDARY STATE')
      call check(printed('COR') .and. printed(' IX  IY'), 'PRINT BOUNDARY STATE header')
      call check_equal(count(index(lines, '   1   1') > 0), 4, 'STATE: four rows with codes 1 1')
      call run('PRINT BOUNDARY FORCES')
      ! (0,0): 0.5 (2, 0) + 0.5 (0, 4) = (1, 2) in the increment columns
      call check(printed('1.00000E+00   2.00000E+00'), 'FORCES: increment of corner (0,0)')
      call run('PRINT BOUNDARY')
      call check(printed('BOUNDARY STATE') .and. printed('BOUNDARY FORCES') .and. &
                 printed('BOUNDARY DISPLACEMENTS'), 'PRINT BOUNDARY: all three tables')
      call run('PRINT 0.5,1.5 -0.5,1.5 BOUNDARY DISP')
      call check_equal(count(index(lines, 'E+00') > 0 .or. index(lines, 'E-') > 0), 2, &
                       'PRINT range BOUNDARY DISP: the two corners at x = 1')
   end subroutine test_print_boundary

   !> CORNER ic1 ic2 on the 2 x 2 assembly: clockwise from (0,0) up the left
   !> side and along the top to (2,2): 7 points (both blocks' corners at (0,1)
   !> and (1,2)).
   subroutine test_corner_walk()
      integer(ip) :: c1, c2
      character(len=80) :: text
      call assembly_2x2()
      call run('BOUND XMUL 1')
      c1 = corner_at(0.0_wp, 0.0_wp, 0.5_wp, 0.5_wp)
      c2 = corner_at(2.0_wp, 2.0_wp, 1.5_wp, 1.5_wp)
      write (text, '(a,i0,1x,i0,a)') 'BOUND CORNER ', c1, c2, ' YLOAD 1.0'
      call run(trim(text))
      associate (b => session%model%bound)
         call check_close(sum(b%dfy(1:b%n)), 7.0_wp, tol, 'CORNER walk: 7 points loaded')
         call check(b%iy(boundary_index(b, corner_at(2.0_wp, 0.0_wp, 1.5_wp, 0.5_wp))) == &
                    bc_free, 'CORNER walk: (2,0) not on the way')
      end associate
      call run('BOUND CORNER 9999 1 XLOAD 1')
      call check(printed('no corner has address 9999'), 'CORNER: unknown corner is an error')
      call run('BOUND 0,1 0,1 CORNER 1 2 XLOAD 1')
      call check(printed('not both'), 'CORNER with a range is an error')
   end subroutine test_corner_walk

end program test_boundary
