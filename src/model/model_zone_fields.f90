!> Derived zone and gridpoint quantities that PRINT, PLOT and HISTORY share
!> (manual Sections 3.14, 4.5, 4.6): zone area and centroid, principal
!> stresses, the Mohr-Coulomb and Hoek-Brown strength/stress ratios, nodal
!> averages of zone values, and point queries (zone containing a point,
!> nearest zone, nearest gridpoint). Read-only on the geometry.
!>
!> Stresses are tension positive (manual 4.1). Principal stresses are the
!> in-plane ones (sxx, syy, sxy; szz is not ranked): `smin` is the
!> algebraically smallest, i.e. the most compressive (the manual's major
!> principal stress s1 when compression is negative), `smax` the largest
!> (the minor principal stress s2).
module model_zone_fields
   use core_kinds, only: wp, ip, l1
   use model_properties, only: prop_cohesion, prop_density, prop_friction, prop_hbm, prop_hbs, &
                                 prop_tensile, prop_ucs
   use model_geometry, only: geometry_t
   use model_materials, only: material_table_t
   implicit none
   private
   public :: zone_area, zone_centroid, zone_mass, principal_stresses
   public :: mohr_ratio, hoek_ratio, ratio_cap
   public :: zone_strength_ratio
   public :: gridpoint_average, zone_at_point, nearest_zone, nearest_gridpoint
   public :: any_zones

   !> |F| is capped here: a zone without deviatoric stress (r_a = 0) has an
   !> unbounded strength/stress ratio.
   real(wp), parameter :: ratio_cap = 100.0_wp

contains

   !> Does the geometry hold at least one live zone?
   pure logical function any_zones(geo)
      type(geometry_t), intent(in) :: geo
      any_zones = .false.
      if (geo%zones%n > 0) any_zones = any(geo%zones%live(1:geo%zones%n))
   end function any_zones

   !> Area of zone z from its current gridpoint positions (> 0: counter-clockwise).
   pure real(wp) function zone_area(geo, z) result(a)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: z
      associate (g => geo%gridpoints, i => geo%zones%g1(z), j => geo%zones%g2(z), &
                 k => geo%zones%g3(z))
         a = 0.5_wp*((g%x(j) - g%x(i))*(g%y(k) - g%y(i)) - (g%x(k) - g%x(i))*(g%y(j) - g%y(i)))
      end associate
   end function zone_area

   pure subroutine zone_centroid(geo, z, xc, yc)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: z
      real(wp), intent(out) :: xc, yc
      associate (g => geo%gridpoints, i => geo%zones%g1(z), j => geo%zones%g2(z), &
                 k => geo%zones%g3(z))
         xc = (g%x(i) + g%x(j) + g%x(k))/3.0_wp
         yc = (g%y(i) + g%y(j) + g%y(k))/3.0_wp
      end associate
   end subroutine zone_centroid

   !> Unscaled zone mass: density of the block's material times the area.
   pure real(wp) function zone_mass(geo, materials, z) result(m)
      type(geometry_t), intent(in) :: geo
      type(material_table_t), intent(in) :: materials
      integer(ip), intent(in) :: z
      m = materials%get(int(geo%blocks%material(geo%zones%block(z))), prop_density)* &
          zone_area(geo, z)
   end function zone_mass

   !> In-plane principal stresses of (sxx, syy, sxy): smin <= smax, and the
   !> direction of smin in degrees from +x, counter-clockwise, in (-90, 90].
   pure subroutine principal_stresses(sxx, syy, sxy, smin, smax, angle)
      real(wp), intent(in) :: sxx, syy, sxy
      real(wp), intent(out) :: smin, smax, angle
      real(wp), parameter :: deg = 57.29577951308232_wp
      real(wp) :: c, r
      c = 0.5_wp*(sxx + syy)
      r = hypot(0.5_wp*(sxx - syy), sxy)
      smin = c - r
      smax = c + r
      ! smax lies at 0.5 atan2(2 sxy, sxx - syy); smin is perpendicular to it
      angle = 0.5_wp*atan2(2.0_wp*sxy, sxx - syy)*deg + 90.0_wp
      if (angle > 90.0_wp) angle = angle - 180.0_wp
      if (angle <= -90.0_wp) angle = angle + 180.0_wp
   end subroutine principal_stresses

   !> Mohr-Coulomb strength/stress ratio F = r_b / r_a (manual 3.14.1) of
   !> principal stresses smin <= smax (tension positive) for cohesion `coh`,
   !> friction coefficient `fric` (tan phi) and tensile strength `tens`.
   !> In compression-positive terms s1 = -smin, s3 = -smax; holding s3, the
   !> failure circle has radius r_b = (c cos phi + s3 sin phi) / (1 - sin phi).
   !> F < 0 when smax > 0 (tension present); F = 0 when smax exceeds the
   !> tension cut-off min(TENS, COH/FRIC).
   pure real(wp) function mohr_ratio(smin, smax, coh, fric, tens) result(f)
      real(wp), intent(in) :: smin, smax, coh, fric, tens
      real(wp) :: cutoff, phi, rb, ra
      cutoff = tens
      if (fric > 0.0_wp) cutoff = min(tens, coh/fric)
      f = 0.0_wp
      if (smax > cutoff) return
      phi = atan(fric)
      rb = (coh*cos(phi) - smax*sin(phi))/(1.0_wp - sin(phi))
      ra = 0.5_wp*(smax - smin)
      f = capped(max(rb, 0.0_wp), ra)
      if (smax > 0.0_wp) f = -f
   end function mohr_ratio

   !> Hoek-Brown strength/stress ratio (manual 3.14.2). With compression
   !> positive, s1 = -smin, s3 = -smax, the criterion is
   !> s1f = s3 + sqrt(m ucs s3 + s ucs^2), so r_b = sqrt(m ucs s3 + s ucs^2)/2.
   !> F < 0 when smax > 0; F = 0 when smax > s ucs / m (no real strength).
   pure real(wp) function hoek_ratio(smin, smax, hbs, hbm, ucs) result(f)
      real(wp), intent(in) :: smin, smax, hbs, hbm, ucs
      real(wp) :: arg, ra
      f = 0.0_wp
      if (hbm > 0.0_wp) then
         if (smax > hbs*ucs/hbm) return
      end if
      arg = -hbm*ucs*smax + hbs*ucs*ucs
      if (arg <= 0.0_wp) return
      ra = 0.5_wp*(smax - smin)
      f = capped(0.5_wp*sqrt(arg), ra)
      if (smax > 0.0_wp) f = -f
   end function hoek_ratio

   pure real(wp) function capped(rb, ra) result(f)
      real(wp), intent(in) :: rb, ra
      if (ra*ratio_cap <= rb) then
         f = ratio_cap
      else
         f = rb/ra
      end if
   end function capped

   !> Strength/stress ratio of zone z by `criterion`: 'MOHR' with its block's
   !> COHESION, FRICTION, TENSILE (TENSILE not given: no cut-off other than
   !> c / tan(phi), as in the CONS 3 zone model); 'HOEK' with HBS, HBM, UCS.
   pure real(wp) function zone_strength_ratio(geo, materials, z, criterion) result(f)
      type(geometry_t), intent(in) :: geo
      type(material_table_t), intent(in) :: materials
      integer(ip), intent(in) :: z
      character(len=*), intent(in) :: criterion
      real(wp) :: smin, smax, angle
      integer :: m
      m = geo%blocks%material(geo%zones%block(z))
      call principal_stresses(geo%zones%sxx(z), geo%zones%syy(z), geo%zones%sxy(z), &
                              smin, smax, angle)
      select case (criterion)
      case ('HOEK')
         f = hoek_ratio(smin, smax, materials%get(m, prop_hbs), materials%get(m, prop_hbm), &
                        materials%get(m, prop_ucs))
      case default
         f = mohr_ratio(smin, smax, materials%get(m, prop_cohesion), &
                        materials%get(m, prop_friction), &
                        merge(materials%get(m, prop_tensile), huge(1.0_wp), &
                              materials%is_given(m, prop_tensile)))
      end select
   end function zone_strength_ratio

   !> Nodal values from zone values: at each live gridpoint, the area-weighted
   !> mean of the values of the live zones that use it (0 if none). Zones
   !> and gridpoints belong to one block, so no value crosses a joint.
   subroutine gridpoint_average(geo, zval, gval)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: zval(:)
      real(wp), allocatable, intent(out) :: gval(:)
      real(wp), allocatable :: wsum(:)
      integer(ip) :: z
      integer :: k
      integer(ip) :: g(3)
      real(wp) :: a
      allocate (gval(geo%gridpoints%n), wsum(geo%gridpoints%n))
      gval = 0.0_wp
      wsum = 0.0_wp
      do z = 1, geo%zones%n
         if (.not. geo%zones%live(z)) cycle
         a = abs(zone_area(geo, z))
         g = [geo%zones%g1(z), geo%zones%g2(z), geo%zones%g3(z)]
         do k = 1, 3
            gval(g(k)) = gval(g(k)) + a*zval(z)
            wsum(g(k)) = wsum(g(k)) + a
         end do
      end do
      where (wsum > 0.0_wp) gval = gval/wsum
   end subroutine gridpoint_average

   !> Lowest-id live zone containing (x, y) (edges included, to a relative
   !> tolerance of 1e-10 of the zone's area); 0 when the point is in none.
   pure integer(ip) function zone_at_point(geo, x, y) result(found)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: x, y
      integer(ip) :: z
      real(wp) :: a, l1, l2, l3, tol
      found = 0
      do z = 1, geo%zones%n
         if (.not. geo%zones%live(z)) cycle
         associate (g => geo%gridpoints, i => geo%zones%g1(z), j => geo%zones%g2(z), &
                    k => geo%zones%g3(z))
            if (x < min(g%x(i), g%x(j), g%x(k)) .or. x > max(g%x(i), g%x(j), g%x(k))) cycle
            if (y < min(g%y(i), g%y(j), g%y(k)) .or. y > max(g%y(i), g%y(j), g%y(k))) cycle
            a = zone_area(geo, z)
            if (a == 0.0_wp) cycle
            tol = -1.0e-10_wp*abs(a)
            l1 = sign(1.0_wp, a)*0.5_wp*((g%x(j) - x)*(g%y(k) - y) - (g%x(k) - x)*(g%y(j) - y))
            l2 = sign(1.0_wp, a)*0.5_wp*((g%x(k) - x)*(g%y(i) - y) - (g%x(i) - x)*(g%y(k) - y))
            l3 = sign(1.0_wp, a)*0.5_wp*((g%x(i) - x)*(g%y(j) - y) - (g%x(j) - x)*(g%y(i) - y))
         end associate
         if (l1 >= tol .and. l2 >= tol .and. l3 >= tol) then
            found = z
            return
         end if
      end do
   end function zone_at_point

   !> Live zone whose centroid is nearest (x, y), ties to the lower id; 0 if none.
   !> `solid`: only zones of blocks that are not excavated (CONS 0).
   pure integer(ip) function nearest_zone(geo, x, y, solid) result(best)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: x, y
      logical, intent(in), optional :: solid
      integer(ip) :: z
      real(wp) :: d, dbest, xc, yc
      best = 0
      dbest = huge(1.0_wp)
      do z = 1, geo%zones%n
         if (.not. searched(geo, geo%zones%live, geo%zones%block, z, solid)) cycle
         call zone_centroid(geo, z, xc, yc)
         d = hypot(xc - x, yc - y)
         if (d < dbest) then
            best = z
            dbest = d
         end if
      end do
   end function nearest_zone

   !> Live gridpoint nearest (x, y), ties to the lower id; 0 if none. `dist`
   !> returns its distance (huge if none). `solid`: only gridpoints of blocks
   !> that are not excavated (CONS 0).
   pure subroutine nearest_gridpoint(geo, x, y, best, dist, solid)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: x, y
      integer(ip), intent(out) :: best
      real(wp), intent(out) :: dist
      logical, intent(in), optional :: solid
      integer(ip) :: g
      real(wp) :: d
      best = 0
      dist = huge(1.0_wp)
      do g = 1, geo%gridpoints%n
         if (.not. searched(geo, geo%gridpoints%live, geo%gridpoints%block, g, solid)) cycle
         d = hypot(geo%gridpoints%x(g) - x, geo%gridpoints%y(g) - y)
         if (d < dist) then
            best = g
            dist = d
         end if
      end do
   end subroutine nearest_gridpoint

   !> Entry k of a zone or gridpoint list (its `live` and `block` arrays)
   !> takes part in nearest_zone / nearest_gridpoint: live, and with `solid`
   !> of a block that is not excavated (CONS 0).
   pure logical function searched(geo, live, block, k, solid) result(ok)
      type(geometry_t), intent(in) :: geo
      logical(l1), intent(in) :: live(:)
      integer(ip), intent(in) :: block(:), k
      logical, intent(in), optional :: solid
      ok = live(k)
      if (.not. ok .or. .not. present(solid)) return
      if (solid) ok = geo%blocks%cons(block(k)) /= 0
   end function searched

end module model_zone_fields
