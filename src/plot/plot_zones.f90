!> PLOT layers of fully-deformable blocks (manual Sections 3.14, 4.6):
!> ZONES, STRESSES (principal stress crosses), TENSION, PLASTICITY and the
!> contour layers SXX SYY (SYX) SXY SMIN SMAX SDIF XDIS YDIS XVEL YVEL MOHR
!> HOEK with the switches GRID, INTERVAL, MAX, ZERO and LINE.
!>
!> Contours are exact for the field they draw: each quantity is a value at
!> every gridpoint (gridpoint displacements and velocities as they are;
!> zone quantities averaged to the gridpoints, area-weighted, within each
!> block) interpolated linearly inside each zone triangle. A band is the
!> part of a triangle between two levels, a convex polygon found by
!> clipping the triangle at both levels, so its edges inside the triangle
!> lie exactly on the iso-lines. Layout and rules: docs/plot.md.
module plot_zones
   use core_kinds, only: wp, ip
   use model_properties, only: prop_cohesion, prop_friction, prop_hbm, prop_ucs
   use model_state, only: model_t
   use model_geometry, only: geometry_t
   use model_zones, only: zone_at_failure, zone_failed_past, zone_tension
   use model_zone_fields, only: principal_stresses, zone_centroid, gridpoint_average, &
                                zone_strength_ratio, zone_at_point, any_zones, &
                                ratio_cap
   use plot_scene, only: plot_scene_t, item_polyline, item_polygon, item_fill, legend_text, &
                         legend_swatch, legend_line, legend_title, legend_bar, black, grey, light_grey, &
                         red, blue, orange, format_number, nice_number, align_centre
   use plot_layers, only: layer_options_t
   use core_output, only: itoa
   use core_strings, only: table_text, text_pair_t
   implicit none
   private
   public :: plot_zone_layer, plot_zone_layer_names, plot_zone_area_layer
   public :: contour_names, contour_levels, clip_band, zone_field, band_colour, max_bands

   !> Layers this module draws (canonical PLOT keyword names).
   character(len=16), parameter :: plot_zone_layer_names(18) = [character(len=16) :: &
      'ZONES', 'STRESSES', 'TENSION', 'PLASTICITY', 'SXX', 'SYY', 'SYX', 'SXY', 'SMIN', &
      'SMAX', 'SDIF', 'XDISPLACEMENT', 'YDISPLACEMENT', 'XVEL', 'YVEL', 'MOHR', 'HOEK', &
      'TEMPERATURE']
   !> The contour layers among them (TEMPERATURE: manual Section 7.4.2).
   character(len=16), parameter :: contour_names(14) = [character(len=16) :: &
      'SXX', 'SYY', 'SYX', 'SXY', 'SMIN', 'SMAX', 'SDIF', 'XDISPLACEMENT', 'YDISPLACEMENT', &
      'XVEL', 'YVEL', 'MOHR', 'HOEK', 'TEMPERATURE']
   !> At most this many bands (or lines): a smaller INTERVAL is widened.
   integer, parameter :: max_bands = 20
   !> Without INTERVAL: at most this many (so the legend keeps room).
   integer, parameter :: default_bands = 12
   !> Default vector-like length of the largest stress cross: 5% of the window.
   real(wp), parameter :: cross_fraction = 0.05_wp

   !> Legend titles of the zone layers (the layer name when absent).
   type(text_pair_t), parameter :: layer_titles(*) = [ &
      text_pair_t('ZONES', 'zones'), &
      text_pair_t('STRESSES', 'principal stresses'), &
      text_pair_t('TENSION', 'zones in tension'), &
      text_pair_t('PLASTICITY', 'plasticity state'), &
      text_pair_t('SXX', 'SXX contours (Pa)'), &
      text_pair_t('SYY', 'SYY contours (Pa)'), &
      text_pair_t('SYX', 'SYY contours (Pa)'), &
      text_pair_t('SXY', 'SXY contours (Pa)'), &
      text_pair_t('SMIN', 'min principal stress (Pa)'), &
      text_pair_t('SMAX', 'max principal stress (Pa)'), &
      text_pair_t('SDIF', 'principal stress difference (Pa)'), &
      text_pair_t('XDISPLACEMENT', 'x-displacement contours (m)'), &
      text_pair_t('YDISPLACEMENT', 'y-displacement contours (m)'), &
      text_pair_t('XVEL', 'x-velocity contours (m/s)'), &
      text_pair_t('YVEL', 'y-velocity contours (m/s)'), &
      text_pair_t('TEMPERATURE', 'temperature contours (deg C)'), &
      text_pair_t('MOHR', 'Mohr-Coulomb strength/stress (ratio)'), &
      text_pair_t('HOEK', 'Hoek-Brown strength/stress (ratio)')]

contains

   !> Layers that fill areas (drawn before line layers, as MAT).
   pure logical function plot_zone_area_layer(name)
      character(len=*), intent(in) :: name
      plot_zone_area_layer = any(contour_names == name) .or. name == 'TENSION'
   end function plot_zone_area_layer

   !> Draw layer `name` (one of `plot_zone_layer_names`).
   subroutine plot_zone_layer(scene, model, name, opts)
      type(plot_scene_t), intent(inout) :: scene
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: name
      type(layer_options_t), intent(in) :: opts
      if (.not. any_zones(model%geometry)) then
         call scene%add_legend(legend_title, trim(title_of(name)))
         call scene%add_legend(legend_text, '(no zones: GENERATE the FDEF blocks)')
         return
      end if
      select case (name)
      case ('ZONES')
         call layer_zones(scene, model%geometry, grey, 0.6_wp, .true.)
      case ('STRESSES')
         call layer_stress_crosses(scene, model%geometry, opts)
      case ('TENSION')
         call layer_tension(scene, model, opts%as_lines)
      case ('PLASTICITY')
         call layer_plasticity(scene, model%geometry)
      case default
         call layer_contours(scene, model, name, opts)
      end select
   end subroutine plot_zone_layer

   !> Legend title of a layer.
   function title_of(name) result(t)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: t
      t = table_text(layer_titles, name, name)
   end function title_of

   !> Zone outlines.
   subroutine layer_zones(scene, geo, colour, width, legend)
      type(plot_scene_t), intent(inout) :: scene
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: colour(3), width
      logical, intent(in) :: legend
      integer(ip) :: z, count
      real(wp) :: x(3), y(3)
      count = 0
      do z = 1, geo%zones%n
         if (.not. geo%zones%live(z)) cycle
         call vertices(geo, z, x, y)
         call scene%world_polyline(item_polygon, x, y, colour, width)
         count = count + 1
      end do
      if (legend) call scene%add_legend(legend_line, 'zones ('//itoa(int(count))//')', &
                                        colour=colour, width=width)
   end subroutine layer_zones

   pure subroutine vertices(geo, z, x, y)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: z
      real(wp), intent(out) :: x(3), y(3)
      x = [geo%gridpoints%x(geo%zones%g1(z)), geo%gridpoints%x(geo%zones%g2(z)), &
           geo%gridpoints%x(geo%zones%g3(z))]
      y = [geo%gridpoints%y(geo%zones%g1(z)), geo%gridpoints%y(geo%zones%g2(z)), &
           geo%gridpoints%y(geo%zones%g3(z))]
   end subroutine vertices

   !> Principal stresses of each zone as a cross at its centroid: one bar
   !> along each principal direction, of window length |s| * sc (without sc
   !> the largest is 5% of the window), compression blue, tension red.
   subroutine layer_stress_crosses(scene, geo, opts)
      type(plot_scene_t), intent(inout) :: scene
      type(geometry_t), intent(in) :: geo
      type(layer_options_t), intent(in) :: opts
      integer(ip) :: z
      integer :: k
      real(wp) :: smin, smax, angle, smaxabs, sc, xc, yc, s(2), a, h, wsize
      real(wp), parameter :: rad = 0.017453292519943295_wp
      smaxabs = 0.0_wp
      do z = 1, geo%zones%n
         if (.not. geo%zones%live(z)) cycle
         call principal_stresses(geo%zones%sxx(z), geo%zones%syy(z), geo%zones%sxy(z), &
                                 smin, smax, angle)
         smaxabs = max(smaxabs, abs(smin), abs(smax))
      end do
      call scene%add_legend(legend_title, 'principal stresses')
      call scene%add_legend(legend_text, 'maximum |s| = '//format_number(smaxabs))
      wsize = max(scene%window(2) - scene%window(1), scene%window(4) - scene%window(3))
      sc = 0.0_wp
      if (opts%has_scale) then
         sc = opts%scale
      else if (smaxabs > 0.0_wp) then
         sc = cross_fraction*wsize/smaxabs
      end if
      if (sc <= 0.0_wp .or. smaxabs <= 0.0_wp) then
         call scene%add_legend(legend_text, '(all stresses are zero)')
         return
      end if
      do z = 1, geo%zones%n
         if (.not. geo%zones%live(z)) cycle
         call principal_stresses(geo%zones%sxx(z), geo%zones%syy(z), geo%zones%sxy(z), &
                                 smin, smax, angle)
         call zone_centroid(geo, z, xc, yc)
         s = [smin, smax]
         do k = 1, 2
            a = (angle + real(k - 1, wp)*90.0_wp)*rad
            h = 0.5_wp*sc*abs(s(k))
            if (h <= 0.0_wp) cycle
            call scene%world_polyline(item_polyline, [xc - h*cos(a), xc + h*cos(a)], &
                                      [yc - h*sin(a), yc + h*sin(a)], &
                                      merge(red, blue, s(k) > 0.0_wp), 1.4_wp)
         end do
      end do
      call scene%add_legend(legend_line, 'compression', colour=blue, width=1.4_wp)
      call scene%add_legend(legend_line, 'tension', colour=red, width=1.4_wp)
      call scene%add_legend(legend_text, 'bar length = |s| x '//format_number(sc))
   end subroutine layer_stress_crosses

   !> Zones with a tensile principal stress (SMAX > 0) filled, and the line
   !> SMAX = 0 of the nodal field separating tension from compression.
   subroutine layer_tension(scene, model, line_only)
      type(plot_scene_t), intent(inout) :: scene
      type(model_t), intent(in) :: model
      logical, intent(in) :: line_only     !< with a filled contour: no pink zones
      real(wp), parameter :: pink(3) = [1.0_wp, 0.72_wp, 0.72_wp]
      real(wp), allocatable :: gval(:), zval(:)
      integer(ip) :: z, count
      real(wp) :: x(3), y(3), smin, smax, angle
      associate (geo => model%geometry)
         allocate (zval(geo%zones%n))
         count = 0
         do z = 1, geo%zones%n
            zval(z) = 0.0_wp
            if (.not. geo%zones%live(z)) cycle
            call principal_stresses(geo%zones%sxx(z), geo%zones%syy(z), geo%zones%sxy(z), &
                                    smin, smax, angle)
            zval(z) = smax
            if (smax <= 0.0_wp) cycle
            count = count + 1
            if (line_only) cycle
            call vertices(geo, z, x, y)
            call scene%world_polyline(item_fill, x, y, pink)
         end do
         call gridpoint_average(geo, zval, gval)
         call iso_lines(scene, geo, gval, [0.0_wp], reshape(red, [3, 1]), 2.0_wp)
      end associate
      call scene%add_legend(legend_title, 'tension')
      if (line_only) then
         call scene%add_legend(legend_text, 'zones in tension: '//itoa(int(count))// &
                               ' (not filled: a contour is filled)')
      else
         call scene%add_legend(legend_swatch, 'zones in tension ('//itoa(int(count))//')', &
                               colour=pink)
      end if
      call scene%add_legend(legend_line, 'SMAX = 0', colour=red, width=2.0_wp)
   end subroutine layer_tension

   !> Plasticity indicator of each zone as a symbol at its centroid: at
   !> failure a filled red disc, failed in the past an open blue circle,
   !> tensile failure an orange cross; elastic zones get none.
   subroutine layer_plasticity(scene, geo)
      type(plot_scene_t), intent(inout) :: scene
      type(geometry_t), intent(in) :: geo
      integer(ip) :: z
      integer :: n(3), k
      real(wp) :: xc, yc, px, py, cx(12), cy(12)
      real(wp), parameter :: r = 4.0_wp
      n = 0
      do k = 1, 12
         cx(k) = r*cos(real(k, wp)*0.5235987755982988_wp)
         cy(k) = r*sin(real(k, wp)*0.5235987755982988_wp)
      end do
      do z = 1, geo%zones%n
         if (.not. geo%zones%live(z)) cycle
         call zone_centroid(geo, z, xc, yc)
         call scene%to_page(xc, yc, px, py)
         select case (geo%zones%state(z))
         case (zone_at_failure)
            call scene%polyline(item_fill, px + cx, py + cy, red, clip=.true.)
            n(1) = n(1) + 1
         case (zone_failed_past)
            call scene%polyline(item_polygon, px + cx, py + cy, blue, 1.2_wp, clip=.true.)
            n(2) = n(2) + 1
         case (zone_tension)
            call scene%polyline(item_polyline, [px - r, px + r], [py - r, py + r], orange, &
                                1.6_wp, clip=.true.)
            call scene%polyline(item_polyline, [px - r, px + r], [py + r, py - r], orange, &
                                1.6_wp, clip=.true.)
            n(3) = n(3) + 1
         end select
      end do
      call scene%add_legend(legend_title, 'plasticity state')
      call scene%add_legend(legend_swatch, 'at failure ('//itoa(n(1))//')', colour=red)
      call scene%add_legend(legend_line, 'failed in the past ('//itoa(n(2))//'), circle', &
                            colour=blue, width=1.2_wp)
      call scene%add_legend(legend_line, 'tensile failure ('//itoa(n(3))//'), cross', &
                            colour=orange, width=1.6_wp)
   end subroutine layer_plasticity

   !> Gridpoint values of contour quantity `name` (0 at dead gridpoints).
   subroutine zone_field(model, name, gval)
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: name
      real(wp), allocatable, intent(out) :: gval(:)
      real(wp), allocatable :: zval(:)
      real(wp) :: smin, smax, angle
      integer(ip) :: z, n
      associate (geo => model%geometry, gp => model%geometry%gridpoints, &
                 zn => model%geometry%zones)
         select case (name)
         case ('XDISPLACEMENT')
            gval = gp%ux(1:gp%n)
         case ('YDISPLACEMENT')
            gval = gp%uy(1:gp%n)
         case ('XVEL')
            gval = gp%vx(1:gp%n)
         case ('YVEL')
            gval = gp%vy(1:gp%n)
         case ('TEMPERATURE')
            ! gridpoint temperatures (0 before THERMAL or INITEM)
            allocate (gval(gp%n))
            gval = 0.0_wp
            if (allocated(model%thermal)) then
               if (allocated(model%thermal%temp)) then
                  n = min(gp%n, size(model%thermal%temp, kind=ip))
                  gval(1:n) = model%thermal%temp(1:n)
               end if
            end if
         case default
            allocate (zval(zn%n))
            zval = 0.0_wp
            do z = 1, zn%n
               if (.not. zn%live(z)) cycle
               call principal_stresses(zn%sxx(z), zn%syy(z), zn%sxy(z), smin, smax, angle)
               select case (name)
               case ('SXX'); zval(z) = zn%sxx(z)
               case ('SYY', 'SYX'); zval(z) = zn%syy(z)
               case ('SXY'); zval(z) = zn%sxy(z)
               case ('SMIN'); zval(z) = smin
               case ('SMAX'); zval(z) = smax
               case ('SDIF'); zval(z) = smax - smin
               case ('MOHR', 'HOEK')
                  zval(z) = zone_strength_ratio(geo, model%materials, z, name)
               end select
            end do
            call gridpoint_average(geo, zval, gval)
         end select
         where (.not. gp%live(1:gp%n)) gval = 0.0_wp
      end associate
   end subroutine zone_field

   !> Contour levels: band edges e(0..n) covering [lo, hi]. Without MAX the
   !> range is the data range widened to multiples of the interval; with
   !> MAX vmax vmin it is [vmin, vmax] exactly, with the multiples of the
   !> interval inside as the other edges. The interval is INTERVAL d, or the
   !> 1-2-5 number below a tenth of the range, widened (doubled) until there
   !> are at most max_bands bands.
   subroutine contour_levels(fmin, fmax, opts, edges, interval)
      real(wp), intent(in) :: fmin, fmax
      type(layer_options_t), intent(in) :: opts
      real(wp), allocatable, intent(out) :: edges(:)
      real(wp), intent(out) :: interval
      real(wp) :: lo, hi, d, e
      integer :: k0, k1, k
      lo = fmin
      hi = fmax
      if (opts%has_max) then
         lo = opts%vmin
         hi = opts%vmax
      end if
      if (hi <= lo) then
         edges = [lo - 0.5_wp*max(abs(lo), 1.0_wp), lo + 0.5_wp*max(abs(lo), 1.0_wp)]
         if (lo == 0.0_wp) edges = [-0.5_wp, 0.5_wp]
         interval = edges(2) - edges(1)
         if (opts%has_interval) interval = opts%interval
         return
      end if
      if (opts%has_interval) then
         d = opts%interval
         do while ((hi - lo)/d > real(max_bands, wp))
            d = 2.0_wp*d
         end do
      else
         d = nice_number((hi - lo)/8.0_wp)
         do while ((hi - lo)/d > real(default_bands, wp))
            d = 2.0_wp*d
         end do
      end if
      interval = d
      k0 = floor(lo/d)
      k1 = ceiling(hi/d)
      allocate (edges(0))
      if (opts%has_max) then
         edges = [lo]
         do k = k0, k1
            e = real(k, wp)*d
            if (e > lo + 1.0e-9_wp*d .and. e < hi - 1.0e-9_wp*d) edges = [edges, e]
         end do
         edges = [edges, hi]
      else
         do k = k0, k1
            edges = [edges, real(k, wp)*d]
         end do
         if (size(edges) < 2) edges = [edges, real(k1 + 1, wp)*d]
      end if
   end subroutine contour_levels

   !> The part of triangle (x, y) where lo <= f <= hi, f linear with vertex
   !> values f: clip at f >= lo, then at f <= hi (Sutherland-Hodgman). The
   !> result is convex with at most 5 vertices; n = 0 when empty.
   pure subroutine clip_band(x, y, f, lo, hi, px, py, n)
      real(wp), intent(in) :: x(3), y(3), f(3), lo, hi
      real(wp), intent(out) :: px(7), py(7)
      integer, intent(out) :: n
      real(wp) :: ax(7), ay(7), af(7), bx(7), by(7), bf(7)
      integer :: m
      ax(1:3) = x
      ay(1:3) = y
      af(1:3) = f
      m = 3
      call clip(ax, ay, af, m, lo, 1.0_wp, bx, by, bf, n)
      call clip(bx, by, bf, n, hi, -1.0_wp, ax, ay, af, m)
      n = m
      px = 0.0_wp
      py = 0.0_wp
      px(1:n) = ax(1:n)
      py(1:n) = ay(1:n)
   contains
      !> Keep the part where s*(f - level) >= 0.
      pure subroutine clip(ix, iy, fi, ni, level, s, ox, oy, of, no)
         real(wp), intent(in) :: ix(7), iy(7), fi(7), level, s
         integer, intent(in) :: ni
         real(wp), intent(out) :: ox(7), oy(7), of(7)
         integer, intent(out) :: no
         integer :: i, j
         real(wp) :: di, dj, t
         no = 0
         ox = 0.0_wp
         oy = 0.0_wp
         of = 0.0_wp
         do i = 1, ni
            j = modulo(i, ni) + 1
            di = s*(fi(i) - level)
            dj = s*(fi(j) - level)
            if (di >= 0.0_wp) then
               no = no + 1
               ox(no) = ix(i); oy(no) = iy(i); of(no) = fi(i)
            end if
            ! a strict sign change: a vertex on the level is kept as a vertex
            if ((di > 0.0_wp .and. dj < 0.0_wp) .or. (di < 0.0_wp .and. dj > 0.0_wp)) then
               t = di/(di - dj)
               no = no + 1
               ox(no) = ix(i) + t*(ix(j) - ix(i))
               oy(no) = iy(i) + t*(iy(j) - iy(i))
               of(no) = level
            end if
         end do
      end subroutine clip
   end subroutine clip_band

   !> Colour of band k of n: blue (low) through cyan, green, yellow to red.
   pure function band_colour(k, n) result(c)
      integer, intent(in) :: k, n
      real(wp) :: c(3)
      real(wp), parameter :: ramp(3, 5) = reshape([ &
         0.20_wp, 0.35_wp, 0.95_wp, 0.25_wp, 0.85_wp, 0.95_wp, 0.35_wp, 0.85_wp, 0.35_wp, &
         0.98_wp, 0.92_wp, 0.25_wp, 0.95_wp, 0.25_wp, 0.20_wp], [3, 5])
      real(wp) :: t, u
      integer :: i
      t = 0.5_wp
      if (n > 1) t = real(k - 1, wp)/real(n - 1, wp)
      u = 4.0_wp*t
      i = min(4, int(u) + 1)
      u = u - real(i - 1, wp)
      c = (1.0_wp - u)*ramp(:, i) + u*ramp(:, i + 1)
   end function band_colour

   !> Filled bands (or LINE contours) of a contour quantity, with GRID
   !> outlines and the legend (range, interval, one entry per band/level).
   subroutine layer_contours(scene, model, name, opts)
      type(plot_scene_t), intent(inout) :: scene
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: name
      type(layer_options_t), intent(in) :: opts
      real(wp), allocatable :: gval(:), edges(:), levels(:), colours(:, :)
      real(wp) :: fmin, fmax, interval, x(3), y(3), f(3), px(7), py(7)
      integer(ip) :: z, g
      integer :: k, nb, n
      call zone_field(model, name, gval)
      fmin = huge(1.0_wp)
      fmax = -huge(1.0_wp)
      associate (geo => model%geometry)
         do z = 1, geo%zones%n
            if (.not. geo%zones%live(z)) cycle
            do g = 1, 3
               f(1) = gval(corner_of(geo, z, int(g)))
               fmin = min(fmin, f(1))
               fmax = max(fmax, f(1))
            end do
         end do
         call contour_levels(fmin, fmax, opts, edges, interval)
         nb = size(edges) - 1
         call scene%add_legend(legend_title, trim(title_of(name)))
         call scene%add_legend(legend_text, 'minimum '//format_number(fmin)//', maximum '// &
                               format_number(fmax))
         call scene%add_legend(legend_text, 'interval '//format_number(interval))
         if (opts%as_lines) call scene%add_legend(legend_text, &
                                                  'drawn as lines (one filled contour per plot)')
         if (name == 'MOHR' .or. name == 'HOEK') then
            call scene%add_legend(legend_text, 'F < 0 tension, 0 beyond cut-off, cap '// &
                                  format_number(ratio_cap))
            call missing_strength(scene, model, name)
         end if
         if (opts%line) then
            allocate (levels(0))
            do k = 1, nb + 1
               if (edges(k) < fmin .or. edges(k) > fmax) cycle     ! no line to draw
               if (opts%zero .and. abs(edges(k)) <= 1.0e-9_wp*interval) cycle
               levels = [levels, edges(k)]
            end do
            allocate (colours(3, size(levels)))
            do k = 1, size(levels)
               colours(:, k) = band_colour(k, size(levels))
            end do
            call iso_lines(scene, geo, gval, levels, colours, 1.5_wp)
            if (any(opts%line_xy /= 0.0_wp)) call label_line(scene, geo, gval, levels, opts)
            do k = size(levels), 1, -1
               call scene%add_legend(legend_line, format_number(levels(k)), &
                                     colour=colours(:, k), width=1.5_wp)
            end do
         else
            do z = 1, geo%zones%n
               if (.not. geo%zones%live(z)) cycle
               call vertices(geo, z, x, y)
               f = [gval(geo%zones%g1(z)), gval(geo%zones%g2(z)), gval(geo%zones%g3(z))]
               do k = 1, nb
                  if (edges(k + 1) < minval(f) .or. edges(k) > maxval(f)) cycle
                  call clip_band(x, y, f, edges(k), edges(k + 1), px, py, n)
                  if (n >= 3) call scene%world_polyline(item_fill, px(1:n), py(1:n), &
                                                        band_colour(k, nb))
               end do
            end do
            ! the colour bar: one band per interval, its edges labelled
            do k = nb, 1, -1
               call scene%add_legend(legend_bar, format_number(edges(k + 1)), &
                                     colour=band_colour(k, nb), low=format_number(edges(k)))
            end do
         end if
         if (opts%grid) call layer_zones(scene, geo, light_grey, 0.5_wp, .false.)
      end associate
   end subroutine layer_contours

   !> A legend line per material of the zoned blocks that lacks the strength
   !> properties of the ratio (HOEK: UCS or HBM; MOHR: both COHESION and
   !> FRICTION): its F is 0 everywhere, which would read as "no strength".
   subroutine missing_strength(scene, model, name)
      type(plot_scene_t), intent(inout) :: scene
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: name
      logical, allocatable :: seen(:)
      integer(ip) :: z
      integer :: m
      logical :: lacks
      associate (geo => model%geometry, mt => model%materials)
         m = max(0, mt%nmat)
         if (geo%blocks%n > 0) m = max(m, maxval(geo%blocks%material(1:geo%blocks%n)))
         allocate (seen(0:m))
         seen = .false.
         do z = 1, geo%zones%n
            if (.not. geo%zones%live(z)) cycle
            m = geo%blocks%material(geo%zones%block(z))
            if (m < 0 .or. m > ubound(seen, 1)) cycle
            if (seen(m)) cycle
            seen(m) = .true.
            if (name == 'HOEK') then
               lacks = .not. (mt%is_given(m, prop_ucs) .and. mt%is_given(m, prop_hbm))
               if (lacks) call scene%add_legend(legend_text, 'material '//itoa(m)// &
                                                ': UCS / HBM not given (F = 0)')
            else
               lacks = .not. (mt%is_given(m, prop_cohesion) .or. mt%is_given(m, prop_friction))
               if (lacks) call scene%add_legend(legend_text, 'material '//itoa(m)// &
                                                ': COHESION / FRICTION not given (F = 0)')
            end if
         end do
      end associate
   end subroutine missing_strength

   pure integer(ip) function corner_of(geo, z, k) result(g)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: z
      integer, intent(in) :: k
      select case (k)
      case (1); g = geo%zones%g1(z)
      case (2); g = geo%zones%g2(z)
      case default; g = geo%zones%g3(z)
      end select
   end function corner_of

   !> The segment of each zone where the nodal field equals each level.
   subroutine iso_lines(scene, geo, gval, levels, colours, width)
      type(plot_scene_t), intent(inout) :: scene
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: gval(:), levels(:), colours(:, :), width
      integer(ip) :: z
      integer :: k, i, j, m
      real(wp) :: x(3), y(3), f(3), sx(3), sy(3), t
      do z = 1, geo%zones%n
         if (.not. geo%zones%live(z)) cycle
         call vertices(geo, z, x, y)
         f = [gval(geo%zones%g1(z)), gval(geo%zones%g2(z)), gval(geo%zones%g3(z))]
         do k = 1, size(levels)
            if (levels(k) < minval(f) .or. levels(k) > maxval(f)) cycle
            if (minval(f) == maxval(f)) cycle
            m = 0
            do i = 1, 3
               j = modulo(i, 3) + 1
               ! crossing on edge i-j, counting a vertex on the level once
               if ((f(i) - levels(k))*(f(j) - levels(k)) < 0.0_wp .or. &
                   (f(i) == levels(k) .and. f(j) /= levels(k))) then
                  t = (levels(k) - f(i))/(f(j) - f(i))
                  m = m + 1
                  sx(m) = x(i) + t*(x(j) - x(i))
                  sy(m) = y(i) + t*(y(j) - y(i))
               end if
            end do
            if (m >= 2) call scene%world_polyline(item_polyline, sx(1:2), sy(1:2), &
                                                  colours(:, k), width)
         end do
      end do
   end subroutine iso_lines

   !> LINE x1 y1 x2 y2: the value of each level written where the segment
   !> crosses its contour (the field sampled at 400 points along it).
   subroutine label_line(scene, geo, gval, levels, opts)
      type(plot_scene_t), intent(inout) :: scene
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: gval(:), levels(:)
      type(layer_options_t), intent(in) :: opts
      integer, parameter :: nsample = 400
      integer :: i, k
      real(wp) :: x, y, f, fprev, xprev, yprev, t, px, py
      logical :: have, prev_have
      prev_have = .false.
      fprev = 0.0_wp
      xprev = 0.0_wp
      yprev = 0.0_wp
      do i = 0, nsample
         t = real(i, wp)/real(nsample, wp)
         x = opts%line_xy(1) + t*(opts%line_xy(3) - opts%line_xy(1))
         y = opts%line_xy(2) + t*(opts%line_xy(4) - opts%line_xy(2))
         call field_at(geo, gval, x, y, f, have)
         if (have .and. prev_have) then
            do k = 1, size(levels)
               if ((fprev - levels(k))*(f - levels(k)) < 0.0_wp .or. &
                   (f == levels(k) .and. fprev /= levels(k))) then
                  call scene%to_page(0.5_wp*(x + xprev), 0.5_wp*(y + yprev), px, py)
                  call scene%text(format_number(levels(k)), px, py - 4.0_wp, 9.0_wp, black, &
                                  align=align_centre, clip=.true.)
               end if
            end do
         end if
         prev_have = have
         fprev = f
         xprev = x
         yprev = y
      end do
   end subroutine label_line

   !> The nodal field interpolated at (x, y), if a zone contains the point.
   subroutine field_at(geo, gval, x, y, f, have)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: gval(:), x, y
      real(wp), intent(out) :: f
      logical, intent(out) :: have
      integer(ip) :: z
      real(wp) :: vx(3), vy(3), a, l1, l2
      f = 0.0_wp
      z = zone_at_point(geo, x, y)
      have = z > 0
      if (.not. have) return
      call vertices(geo, z, vx, vy)
      a = (vx(2) - vx(1))*(vy(3) - vy(1)) - (vx(3) - vx(1))*(vy(2) - vy(1))
      l1 = ((vx(2) - x)*(vy(3) - y) - (vx(3) - x)*(vy(2) - y))/a
      l2 = ((vx(3) - x)*(vy(1) - y) - (vx(1) - x)*(vy(3) - y))/a
      f = l1*gval(geo%zones%g1(z)) + l2*gval(geo%zones%g2(z)) + &
          (1.0_wp - l1 - l2)*gval(geo%zones%g3(z))
   end subroutine field_at


end module plot_zones
