!> Zone mechanics of fully-deformable blocks against closed-form answers
!> (issue 6). The zoning is built here by hand (a rectangle of nx by ny
!> cells, each cut by both diagonals into four triangles around a centre
!> gridpoint) so that these checks do not depend on the zone generator;
!> boundary velocities are set through the gridpoint vfix bits.
!>
!> Cases (SI units):
!>  1. Oedometric column under its own weight (rollers on the sides, base
!>     fixed vertically): syy(y) = -rho g (H - y), sxx = szz = nu/(1-nu) syy,
!>     top settlement u = rho g H^2 / (2 M), M = K + 4G/3. Tolerance 1 %
!>     on stresses at mid-height and on the settlement (crossed triangles
!>     reproduce a linear stress field exactly; the rest is damping).
!>  2. Confined (oedometric) compression by a prescribed top velocity:
!>     syy = M eyy, sxx = (K - 2G/3) eyy, exact for uniform strain (1e-6).
!>  3. Pure shear by boundary velocities vx = r x, vy = -r y: sxx = 2G e,
!>     syy = -2G e, sxy = 0 in every zone (1e-6 relative).
!>  4. Mohr-Coulomb (CONS 3, phi = 0, c) in plane-strain compression
!>     between smooth platens, sides free: the vertical stress saturates at
!>     -2c (Tresca), 0.5 %.
!>  5. The same pulled apart: without TENS the only tension limit of a
!>     phi = 0 material is the Tresca line (the apex c / tan(phi) of the
!>     manual, Section 3.14, is at infinity), so syy saturates at +2c; with
!>     TENS = 0 at 0 and with TENS = c/2 at c/2 (the cut-off). 0.5 %.
program test_zone_mechanics
   use core_kinds, only: wp, ip, i8
   use model_properties, only: prop_bulk, prop_cohesion, prop_density, prop_jkn, prop_jks, &
                                 prop_shear, prop_tensile
   use core_error, only: error_t
   use core_output, only: output_t
   use testing, only: check, check_close, testing_finish
   use model_state, only: model_t, model_reset
   use geometry_blocks, only: geometry_add_block
   use model_zones, only: zones_add_gridpoint, zones_add_zone, vfix_x, vfix_y
   use engine_cycle, only: cycle_run
   implicit none
   real(wp), parameter :: rho = 2000.0_wp, bulk = 1.0e8_wp, shear = 6.0e7_wp, g = 10.0_wp

   call column_under_gravity()
   call oedometric_compression()
   call pure_shear()
   call tresca_limit(-1.0_wp, .true., 1.0e6_wp, -2.0_wp, 'tresca compression')
   call tresca_limit(1.0_wp, .false., 0.0_wp, 2.0_wp, 'tresca extension, no TENS')
   call tresca_limit(1.0_wp, .true., 0.0_wp, 0.0_wp, 'tresca extension, TENS 0')
   call tresca_limit(1.0_wp, .true., 0.5e5_wp, 0.5_wp, 'tresca extension, TENS c/2')
   call testing_finish()

contains

   !> One block w x h zoned into nx x ny crossed cells. Returns the model
   !> with density/moduli of material 1 set.
   subroutine zoned_rectangle(m, w, h, nx, ny)
      type(model_t), intent(out) :: m
      real(wp), intent(in) :: w, h
      integer, intent(in) :: nx, ny
      real(wp), allocatable :: x(:), y(:)
      integer(ip) :: b, c, k, id, i, j, nb
      integer(ip), allocatable :: node(:, :), centre(:, :)
      call model_reset(m)
      ! clockwise ring: up the left side, along the top, down the right, back along the bottom
      nb = 2*(nx + ny)
      allocate (x(nb), y(nb))
      k = 0
      do j = 0, ny - 1
         k = k + 1; x(k) = 0.0_wp; y(k) = h*j/ny
      end do
      do i = 0, nx - 1
         k = k + 1; x(k) = w*i/nx; y(k) = h
      end do
      do j = ny, 1, -1
         k = k + 1; x(k) = w; y(k) = h*j/ny
      end do
      do i = nx, 1, -1
         k = k + 1; x(k) = w*i/nx; y(k) = 0.0_wp
      end do
      m%geometry%round = 0.01_wp*min(w/nx, h/ny)
      m%geometry%edge_min = 2.0_wp*m%geometry%round
      m%geometry%tol = 1.0e-9_wp*max(w, h)
      m%geometry%extent = max(w, h)
      m%geometry%block_created = .true.
      call geometry_add_block(m%geometry, x, y, 1_ip, 1_ip, b)
      m%geometry%original_area = w*h
      allocate (node(0:nx, 0:ny), centre(nx, ny))
      node = 0
      m%geometry%blocks%gfirst(b) = m%geometry%gridpoints%n + 1
      c = m%geometry%blocks%first_corner(b)
      do k = 1, m%geometry%blocks%ncorner(b)
         call zones_add_gridpoint(m%geometry%gridpoints, b, c, m%geometry%corners%x(c), &
                                  m%geometry%corners%y(c), id)
         m%geometry%corners%gp(c) = id
         i = nint(m%geometry%corners%x(c)/w*nx)
         j = nint(m%geometry%corners%y(c)/h*ny)
         node(i, j) = id
         c = m%geometry%corners%next(c)
      end do
      do j = 1, ny - 1
         do i = 1, nx - 1
            call zones_add_gridpoint(m%geometry%gridpoints, b, 0_ip, w*i/nx, h*j/ny, node(i, j))
         end do
      end do
      do j = 1, ny
         do i = 1, nx
            call zones_add_gridpoint(m%geometry%gridpoints, b, 0_ip, w*(i - 0.5_wp)/nx, &
                                     h*(j - 0.5_wp)/ny, centre(i, j))
         end do
      end do
      m%geometry%blocks%ngp(b) = m%geometry%gridpoints%n - m%geometry%blocks%gfirst(b) + 1
      m%geometry%blocks%zfirst(b) = m%geometry%zones%n + 1
      do j = 1, ny
         do i = 1, nx
            ! counter-clockwise triangles around the centre
            call zones_add_zone(m%geometry%zones, b, node(i - 1, j - 1), node(i, j - 1), centre(i, j), id)
            call zones_add_zone(m%geometry%zones, b, node(i, j - 1), node(i, j), centre(i, j), id)
            call zones_add_zone(m%geometry%zones, b, node(i, j), node(i - 1, j), centre(i, j), id)
            call zones_add_zone(m%geometry%zones, b, node(i - 1, j), node(i - 1, j - 1), centre(i, j), id)
         end do
      end do
      m%geometry%blocks%nzone(b) = m%geometry%zones%n - m%geometry%blocks%zfirst(b) + 1
      m%geometry%blocks%fdef(b) = .true.
      call m%materials%set(1, prop_density, rho)
      call m%materials%set(1, prop_bulk, bulk)
      call m%materials%set(1, prop_shear, shear)
      call m%materials%set(1, prop_jkn, 1.0e10_wp)
      call m%materials%set(1, prop_jks, 1.0e10_wp)
   end subroutine zoned_rectangle

   !> Fix directions of gridpoints on the lines x = xv (mask bit) etc.
   subroutine fix_where(m, on_line, bits, vx, vy)
      type(model_t), intent(inout) :: m
      interface
         logical function on_line(x, y)
            import :: wp
            real(wp), intent(in) :: x, y
         end function on_line
      end interface
      integer, intent(in) :: bits
      real(wp), intent(in) :: vx, vy
      integer(ip) :: k
      associate (gp => m%geometry%gridpoints)
         do k = 1, gp%n
            if (.not. on_line(gp%x(k), gp%y(k))) cycle
            gp%vfix(k) = ior(gp%vfix(k), bits)
            if (iand(bits, vfix_x) /= 0) gp%vx(k) = vx
            if (iand(bits, vfix_y) /= 0) gp%vy(k) = vy
         end do
      end associate
   end subroutine fix_where

   subroutine cycle(m, n)
      type(model_t), intent(inout) :: m
      integer, intent(in) :: n
      type(output_t) :: out
      type(error_t), allocatable :: error
      out%screen = .false.
      call cycle_run(m, int(n, i8), out, error)
      call check(.not. allocated(error), 'cycle runs without error')
      if (allocated(error)) print '(a)', error%message
   end subroutine cycle

   !> Mean of a zone stress component over zones whose centroid has y in [y0, y1].
   real(wp) function mean_stress(m, comp, y0, y1) result(s)
      type(model_t), intent(in) :: m
      character(len=*), intent(in) :: comp
      real(wp), intent(in) :: y0, y1
      integer(ip) :: z, n
      real(wp) :: yc
      s = 0.0_wp
      n = 0
      associate (zn => m%geometry%zones, gp => m%geometry%gridpoints)
         do z = 1, zn%n
            if (.not. zn%live(z)) cycle
            yc = (gp%y(zn%g1(z)) + gp%y(zn%g2(z)) + gp%y(zn%g3(z)))/3.0_wp
            if (yc < y0 .or. yc > y1) cycle
            select case (comp)
            case ('sxx'); s = s + zn%sxx(z)
            case ('syy'); s = s + zn%syy(z)
            case ('sxy'); s = s + zn%sxy(z)
            case ('szz'); s = s + zn%szz(z)
            end select
            n = n + 1
         end do
      end associate
      if (n > 0) s = s/n
   end function mean_stress

   logical function left_or_right(x, y)
      real(wp), intent(in) :: x, y
      left_or_right = abs(x) < 1.0e-9_wp .or. abs(x - 1.0_wp) < 1.0e-9_wp
   end function left_or_right

   logical function bottom(x, y)
      real(wp), intent(in) :: x, y
      bottom = abs(y) < 1.0e-9_wp
   end function bottom

   logical function top(x, y)
      real(wp), intent(in) :: x, y
      top = abs(y - 4.0_wp) < 1.0e-9_wp
   end function top

   logical function outline(x, y)
      real(wp), intent(in) :: x, y
      outline = abs(x) < 1.0e-9_wp .or. abs(x - 1.0_wp) < 1.0e-9_wp .or. abs(y) < 1.0e-9_wp .or. &
                abs(y - 1.0_wp) < 1.0e-9_wp
   end function outline

   !> Case 1.
   subroutine column_under_gravity()
      type(model_t) :: m
      real(wp) :: h, mmod, nu, syy, sxx, utop, uexact
      integer(ip) :: k
      h = 4.0_wp
      call zoned_rectangle(m, 1.0_wp, h, 2, 8)
      call fix_where(m, left_or_right, vfix_x, 0.0_wp, 0.0_wp)
      call fix_where(m, bottom, vfix_y, 0.0_wp, 0.0_wp)
      m%gravity = [0.0_wp, -g]
      m%mech%damping = 1    ! DAMP AUTO
      call cycle(m, 6000)
      mmod = bulk + 4.0_wp*shear/3.0_wp
      nu = (3.0_wp*bulk - 2.0_wp*shear)/(2.0_wp*(3.0_wp*bulk + shear))
      ! mid-height band y in [1.5, 2.5]: mean depth 2, syy = -rho g 2
      syy = mean_stress(m, 'syy', 1.5_wp, 2.5_wp)
      sxx = mean_stress(m, 'sxx', 1.5_wp, 2.5_wp)
      call check_close(syy, -rho*g*(h - 2.0_wp), 1.0e-2_wp, 'column: syy at mid-height = -rho g (H - y)')
      call check_close(sxx, nu/(1.0_wp - nu)*syy, 1.0e-2_wp, 'column: sxx = nu/(1-nu) syy')
      utop = 0.0_wp
      do k = 1, m%geometry%gridpoints%n
         if (abs(m%geometry%gridpoints%y(k) - h - m%geometry%gridpoints%uy(k)) < 1.0e-6_wp) &
            utop = m%geometry%gridpoints%uy(k)
      end do
      uexact = -rho*g*h*h/(2.0_wp*mmod)
      call check_close(utop, uexact, 1.0e-2_wp, 'column: top settlement rho g H^2 / 2M')
   end subroutine column_under_gravity

   !> Case 2.
   subroutine oedometric_compression()
      type(model_t) :: m
      real(wp) :: v, eyy, t
      call zoned_rectangle(m, 1.0_wp, 4.0_wp, 2, 4)
      v = -1.0e-4_wp
      call fix_where(m, left_or_right, vfix_x, 0.0_wp, 0.0_wp)
      call fix_where(m, bottom, vfix_y, 0.0_wp, 0.0_wp)
      ! every gridpoint moves with the uniform-strain velocity field, so
      ! the answer is exact whatever the inertia
      call fix_where(m, top, vfix_y, 0.0_wp, v)
      call set_linear_vy(m, v/4.0_wp)
      call cycle(m, 200)
      t = m%mech%time
      eyy = v*t/4.0_wp
      call check_close(mean_stress(m, 'syy', 0.0_wp, 4.0_wp), (bulk + 4.0_wp*shear/3.0_wp)*eyy, 1.0e-6_wp, &
                       'oedometer: syy = M eyy')
      call check_close(mean_stress(m, 'sxx', 0.0_wp, 4.0_wp), (bulk - 2.0_wp*shear/3.0_wp)*eyy, 1.0e-6_wp, &
                       'oedometer: sxx = lambda eyy')
   end subroutine oedometric_compression

   !> vy = rate * y at every gridpoint (initial velocity field).
   subroutine set_linear_vy(m, rate)
      type(model_t), intent(inout) :: m
      real(wp), intent(in) :: rate
      integer(ip) :: k
      do k = 1, m%geometry%gridpoints%n
         m%geometry%gridpoints%vy(k) = rate*m%geometry%gridpoints%y(k)
      end do
   end subroutine set_linear_vy

   !> Case 3.
   subroutine pure_shear()
      type(model_t) :: m
      real(wp) :: r, e, smax
      integer(ip) :: k, z
      call zoned_rectangle(m, 1.0_wp, 1.0_wp, 3, 3)
      r = 1.0e-4_wp
      do k = 1, m%geometry%gridpoints%n
         associate (gp => m%geometry%gridpoints)
            gp%vx(k) = r*gp%x(k)
            gp%vy(k) = -r*gp%y(k)
            if (outline(gp%x(k), gp%y(k))) gp%vfix(k) = ior(vfix_x, vfix_y)
         end associate
      end do
      call cycle(m, 100)
      ! strain from the actual displacement of a boundary point (large-strain
      ! updates make it differ from r t by O(e^2))
      e = r*m%mech%time
      smax = 0.0_wp
      do z = 1, m%geometry%zones%n
         smax = max(smax, abs(m%geometry%zones%sxx(z) - 2.0_wp*shear*e), &
                    abs(m%geometry%zones%syy(z) + 2.0_wp*shear*e), abs(m%geometry%zones%sxy(z)))
      end do
      call check(smax <= 1.0e-3_wp*2.0_wp*shear*e, 'pure shear: sxx = 2Ge, syy = -2Ge, sxy = 0 in every zone')
   end subroutine pure_shear

   !> Cases 4 and 5: plane-strain compression (vsign -1) or extension
   !> (vsign +1) of a Tresca material (CONS 3, phi = 0) by prescribed
   !> velocities top and bottom, sides free: the vertical stress saturates
   !> at expect*c (sxx = 0, szz between). TENS is set only if tens_given.
   subroutine tresca_limit(vsign, tens_given, tens, expect, label)
      real(wp), intent(in) :: vsign, tens, expect
      logical, intent(in) :: tens_given
      character(len=*), intent(in) :: label
      type(model_t) :: m
      real(wp) :: coh, syy
      integer(ip) :: k
      coh = 1.0e5_wp
      call zoned_rectangle(m, 1.0_wp, 1.0_wp, 3, 3)
      m%geometry%blocks%cons(1) = 3
      call m%materials%set(1, prop_cohesion, coh)
      if (tens_given) call m%materials%set(1, prop_tensile, tens)
      do k = 1, m%geometry%gridpoints%n
         associate (gp => m%geometry%gridpoints)
            ! smooth platens (y fixed only), one point pinned in x
            if (abs(gp%y(k)) < 1.0e-9_wp .or. abs(gp%y(k) - 1.0_wp) < 1.0e-9_wp) then
               gp%vfix(k) = vfix_y
               gp%vy(k) = merge(vsign*1.0e-2_wp, 0.0_wp, gp%y(k) > 0.5_wp)
            end if
            if (abs(gp%y(k)) < 1.0e-9_wp .and. abs(gp%x(k)) < 1.0e-9_wp) gp%vfix(k) = ior(vfix_x, vfix_y)
         end associate
      end do
      m%mech%damping = 1
      call cycle(m, 4000)
      syy = mean_stress(m, 'syy', 0.3_wp, 0.7_wp)
      call check(1.0e-2_wp*m%mech%time > 4.0_wp*coh/(bulk + 4.0_wp*shear/3.0_wp), &
                 label//': the strain is well past first yield')
      if (expect == 0.0_wp) then
         call check(abs(syy) <= 5.0e-3_wp*coh, label//': vertical stress saturates at 0')
      else
         call check_close(syy, expect*coh, 5.0e-3_wp, label//': vertical stress saturates')
      end if
   end subroutine tresca_limit

end program test_zone_mechanics
