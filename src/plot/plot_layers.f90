!> Model layers of PLOT for the rigid-block model (manual Section 4.6): each
!> draws one kind of model data into the scene in window coordinates and
!> adds its legend entries. `plot_model_layer` is the one entry point; a
!> later physics (zones, stresses, flow, temperature, structures) adds its
!> names to `plot_layer_names` and a case there (see docs/plot.md).
module plot_layers
   use core_kinds, only: wp, ip, i1
   use model_state, only: model_t
   use model_geometry, only: geometry_t, block_contains_point
   use core_constants, only: pi
   use core_sort, only: counts_to_starts
   use plot_scene, only: plot_scene_t, item_polyline, item_polygon, item_fill, &
                         legend_text, legend_swatch, legend_line, legend_arrow, legend_title, &
                         black, grey, red, blue, dark_green, cyan, purple, orange, magenta, &
                         material_colour, format_number, nice_number, format_tick, align_centre
   use core_output, only: itoa
   implicit none
   private
   public :: layer_options_t, plot_model_layer, plot_layer_names, plot_block_outline
   public :: plot_contact_slip, plot_contact_tension, plot_contact_fractured, draw_vectors
   public :: contact_segment, thick_max
   public :: arrow_set_t, arrows_reserve, arrows_push, arrows_add_gridpoints

   !> Contact state bits, the same values as contact_joint_law's state_slip,
   !> state_tension and state_fractured (test_plot checks that they agree).
   integer(i1), parameter :: plot_contact_slip = 1_i1, plot_contact_tension = 2_i1, plot_contact_fractured = 4_i1

   !> Layers this module draws (canonical PLOT keyword names).
   character(len=16), parameter :: plot_layer_names(18) = [character(len=16) :: &
      'MAT', 'BLOCKS', 'BNUM', 'BOUNDARY', 'CONTACTS', 'DOMAINS', 'VELOCITY', &
      'DISPLACEMENTS', 'SHEAR', 'SLIP', 'CLOSURE', 'WINDOW', 'FRACTURES', 'STRUCT', &
      'CABLE', 'REINFORCE', 'AXIAL', 'CFORCE']

   !> Arrows for draw_vectors: (u, v) at (x, y), the first n entries
   !> (arrows_reserve, arrows_push, arrows_add_gridpoints).
   type :: arrow_set_t
      real(wp), allocatable :: x(:), y(:), u(:), v(:)
      integer :: n = 0
   end type arrow_set_t

   !> Thickest line of the thickness-scaled layers (SHEAR, CLOSURE), page units.
   real(wp), parameter :: thick_max = 8.0_wp
   !> Default vector length of the largest vector: 5% of the window (manual).
   real(wp), parameter :: vector_fraction = 0.05_wp

   !> What a keyword's switches and <sc> say. The contour switches (manual
   !> 4.6, docs/plot.md) belong to the keyword before them.
   type :: layer_options_t
      real(wp) :: scale = 0.0_wp
      logical :: has_scale = .false.
      logical :: nc = .false.          !< no corner rounding on block outlines
      logical :: grid = .false.        !< GRID: zone outlines with the contours
      logical :: has_interval = .false.
      real(wp) :: interval = 0.0_wp    !< INTERVAL d: contour interval
      logical :: has_max = .false.
      real(wp) :: vmax = 0.0_wp, vmin = 0.0_wp   !< MAX vmax vmin: contoured range
      logical :: zero = .false.        !< ZERO: no zero contour line
      logical :: line = .false.        !< LINE x1 y1 x2 y2: line contours, labelled
      real(wp) :: line_xy(4) = 0.0_wp  !<   along that segment
      logical :: as_lines = .false.    !< LINE set because another contour is filled
      !> JLINE / JOINT x1 y1 x2 y2 q <tolc> and ROTATE BLOCK|ZONE (plot_profiles)
      real(wp) :: profile_xy(4) = 0.0_wp
      character(len=8) :: quantity = ''   !< APE FLOW NSTR PP SSTR VEL NDIS SDIS KOFF; BLOCK ZONE
      integer :: koff = 0                 !< contact offset (quantity KOFF)
      logical :: has_tolc = .false.
      real(wp) :: tolc = 0.0_wp
   end type layer_options_t

   !> Block bounding boxes in a uniform grid, for point-in-block queries.
   type :: bins_t
      integer :: nx = 1, ny = 1
      real(wp) :: x0 = 0.0_wp, y0 = 0.0_wp, h = 1.0_wp
      integer, allocatable :: start(:), list(:)
   end type bins_t

contains

   !> Draw layer `name` (one of `plot_layer_names`; plot_build dispatches by
   !> the name lists) of `model` into `scene`.
   subroutine plot_model_layer(scene, model, name, opts)
      type(plot_scene_t), intent(inout) :: scene
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: name
      type(layer_options_t), intent(in) :: opts
      select case (name)
      case ('MAT')
         call layer_materials(scene, model%geometry, opts)
      case ('BLOCKS')
         call layer_blocks(scene, model%geometry, opts)
      case ('BNUM')
         call layer_block_numbers(scene, model%geometry)
      case ('BOUNDARY')
         call layer_boundary(scene, model%geometry)
      case ('CONTACTS')
         call layer_contacts(scene, model%geometry)
      case ('DOMAINS')
         call layer_domains(scene, model%geometry)
      case ('VELOCITY')
         call layer_velocity(scene, model%geometry, opts)
      case ('DISPLACEMENTS')
         call layer_displacement(scene, model%geometry, opts)
      case ('SHEAR')
         call layer_joint_thickness(scene, model%geometry, opts, .true.)
      case ('CLOSURE')
         call layer_joint_thickness(scene, model%geometry, opts, .false.)
      case ('SLIP')
         call layer_slip(scene, model%geometry)
      case ('FRACTURES')
         call layer_fractures(scene, model%geometry)
      case ('WINDOW')
         call layer_window(scene)
      case ('STRUCT')
         call layer_structures(scene, model)
      case ('CABLE', 'REINFORCE', 'AXIAL', 'CFORCE')
         call layer_reinforcement(scene, model, name, opts)
      end select
   end subroutine plot_model_layer

   !> Outline of block `b` as a closed polygon: the corners, or with
   !> rounding the arcs of the rounding circles (manual Fig. 3-3d) joined by
   !> the straight parts of the edges.
   subroutine plot_block_outline(geo, b, rounded, x, y, n)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: b
      logical, intent(in) :: rounded
      real(wp), allocatable, intent(out) :: x(:), y(:)
      integer, intent(out) :: n
      integer(ip) :: c, cp, cn, k
      integer :: j, nseg
      real(wp) :: rx, ry, r, t1x, t1y, t2x, t2y, a1, sweep
      allocate (x(26*geo%blocks%ncorner(b)), y(26*geo%blocks%ncorner(b)))
      n = 0
      c = geo%blocks%first_corner(b)
      do k = 1, geo%blocks%ncorner(b)
         cp = geo%corners%prev(c)
         cn = geo%corners%next(c)
         ! the corner's own rounding circle, as the contacts see it (reduced
         ! where the global rounding would not fit the block)
         r = 0.0_wp
         if (rounded) then
            rx = geo%corners%rx(c)
            ry = geo%corners%ry(c)
            r = geo%corners%radius(c)
         end if
         if (r <= 0.0_wp) then
            n = n + 1
            x(n) = geo%corners%x(c)
            y(n) = geo%corners%y(c)
         else
            call foot(geo%corners%x(cp), geo%corners%y(cp), geo%corners%x(c), &
                      geo%corners%y(c), rx, ry, t1x, t1y)
            call foot(geo%corners%x(c), geo%corners%y(c), geo%corners%x(cn), &
                      geo%corners%y(cn), rx, ry, t2x, t2y)
            a1 = atan2(t1y - ry, t1x - rx)
            ! clockwise from the tangent point on the incoming edge
            sweep = modulo(a1 - atan2(t2y - ry, t2x - rx), 2.0_wp*pi)
            nseg = max(2, min(24, ceiling(sweep/(pi/16.0_wp))))
            do j = 0, nseg
               n = n + 1
               x(n) = rx + r*cos(a1 - sweep*real(j, wp)/real(nseg, wp))
               y(n) = ry + r*sin(a1 - sweep*real(j, wp)/real(nseg, wp))
            end do
         end if
         c = cn
      end do
   contains
      !> Foot of the perpendicular from (px,py) on the line through a and b.
      pure subroutine foot(ax, ay, bx, by, px, py, fx, fy)
         real(wp), intent(in) :: ax, ay, bx, by, px, py
         real(wp), intent(out) :: fx, fy
         real(wp) :: dx, dy, t
         dx = bx - ax; dy = by - ay
         t = ((px - ax)*dx + (py - ay)*dy)/(dx*dx + dy*dy)
         fx = ax + t*dx
         fy = ay + t*dy
      end subroutine foot
   end subroutine plot_block_outline

   subroutine layer_blocks(scene, geo, opts)
      type(plot_scene_t), intent(inout) :: scene
      type(geometry_t), intent(in) :: geo
      type(layer_options_t), intent(in) :: opts
      call block_outlines(scene, geo, opts, .false., black, 1.4_wp)
      call scene%add_legend(legend_title, 'block plot ('// &
                            itoa(count(geo%blocks%live(1:geo%blocks%n)))//' blocks)')
      if (opts%nc) call scene%add_legend(legend_text, 'corners not rounded (NC)')
   end subroutine layer_blocks

   subroutine layer_materials(scene, geo, opts)
      type(plot_scene_t), intent(inout) :: scene
      type(geometry_t), intent(in) :: geo
      type(layer_options_t), intent(in) :: opts
      integer :: m
      call block_outlines(scene, geo, opts, .true., grey, 0.8_wp)
      call scene%add_legend(legend_title, 'block materials')
      associate (live => geo%blocks%live(1:geo%blocks%n), &
                 material => geo%blocks%material(1:geo%blocks%n))
         do m = 0, maxval(material, mask=live)
            if (any(live .and. material == m)) &
               call scene%add_legend(legend_swatch, 'material '//itoa(m), colour=material_colour(m))
         end do
      end associate
   end subroutine layer_materials

   !> The outline of each live block (corners rounded unless NC), filled in
   !> the colour of its material when `filled`, edged in `edge` of `width`.
   subroutine block_outlines(scene, geo, opts, filled, edge, width)
      type(plot_scene_t), intent(inout) :: scene
      type(geometry_t), intent(in) :: geo
      type(layer_options_t), intent(in) :: opts
      logical, intent(in) :: filled
      real(wp), intent(in) :: edge(3)
      real(wp), intent(in) :: width
      real(wp), allocatable :: x(:), y(:)
      integer(ip) :: b
      integer :: n
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         call plot_block_outline(geo, b, .not. opts%nc, x, y, n)
         if (filled) call scene%world_polyline(item_fill, x(1:n), y(1:n), &
                                               material_colour(geo%blocks%material(b)))
         call scene%world_polyline(item_polygon, x(1:n), y(1:n), edge, width)
      end do
   end subroutine block_outlines

   subroutine layer_block_numbers(scene, geo)
      type(plot_scene_t), intent(inout) :: scene
      type(geometry_t), intent(in) :: geo
      real(wp), parameter :: text_size = 11.0_wp   ! cap height (page units)
      integer(ip) :: b, n
      real(wp) :: px, py
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         call scene%to_page(geo%blocks%xc(b), geo%blocks%yc(b), px, py)
         ! the manual's BNUM: block address numbers (the 1989 address that DELETE
         ! BLOCK n takes; model_address), our id while a block has none yet
         n = b
         if (allocated(geo%blocks%addr)) then
            if (geo%blocks%addr(b) > 0) n = geo%blocks%addr(b)
         end if
         call scene%text(itoa(n), px, py - 0.5_wp*text_size, text_size, blue, &
                         align=align_centre, clip=.true.)
      end do
      call scene%add_legend(legend_text, 'block addresses', colour=blue)
   end subroutine layer_block_numbers

   !> Outer boundary: the parts of block edges with no block just outside.
   !> Each edge is sampled at points about one rounding length apart; a
   !> point is outside when the point a fifth of the rounding length beyond
   !> it (outward) lies in no other block. Joints opened by less than that
   !> still count as inside.
   subroutine layer_boundary(scene, geo)
      type(plot_scene_t), intent(inout) :: scene
      type(geometry_t), intent(in) :: geo
      integer(ip) :: b, c, cn, k
      integer :: j, ns, run_start
      real(wp) :: eps, ex, ey, elen, nx, ny, t, qx, qy
      logical :: outside, prev_outside
      type(bins_t) :: bins
      call bins_build(geo, bins)
      eps = max(10.0_wp*geo%tol, 0.2_wp*geo%round)
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         c = geo%blocks%first_corner(b)
         do k = 1, geo%blocks%ncorner(b)
            cn = geo%corners%next(c)
            ex = geo%corners%x(cn) - geo%corners%x(c)
            ey = geo%corners%y(cn) - geo%corners%y(c)
            elen = hypot(ex, ey)
            if (elen > 0.0_wp) then
               nx = -ey/elen     ! outward: left of a clockwise edge
               ny = ex/elen
               ns = max(1, min(64, ceiling(elen/max(geo%round, 1.0e-12_wp))))
               prev_outside = .false.
               run_start = 0
               do j = 0, ns
                  t = (real(j, wp) + 0.5_wp)/real(ns + 1, wp)
                  qx = geo%corners%x(c) + t*ex + eps*nx
                  qy = geo%corners%y(c) + t*ey + eps*ny
                  outside = .not. inside_other(geo, bins, b, qx, qy)
                  if (outside .and. .not. prev_outside) run_start = j
                  if (prev_outside .and. .not. outside) &
                     call draw_run(run_start, j - 1, ns)
                  prev_outside = outside
               end do
               if (prev_outside) call draw_run(run_start, ns, ns)
            end if
            c = cn
         end do
      end do
      call scene%add_legend(legend_line, 'outer boundary', colour=purple, width=3.0_wp)
   contains
      !> Samples j0..j1 cover the edge fractions [j0, j1+1]/(ns+1), widened
      !> to the edge ends when they touch them.
      subroutine draw_run(j0, j1, n)
         integer, intent(in) :: j0, j1, n
         real(wp) :: t0, t1
         t0 = real(j0, wp)/real(n + 1, wp)
         t1 = real(j1 + 1, wp)/real(n + 1, wp)
         if (j1 == n) t1 = 1.0_wp
         call scene%world_polyline(item_polyline, &
                                   [geo%corners%x(c) + t0*ex, geo%corners%x(c) + t1*ex], &
                                   [geo%corners%y(c) + t0*ey, geo%corners%y(c) + t1*ey], &
                                   purple, 3.0_wp)
      end subroutine draw_run
   end subroutine layer_boundary

   subroutine layer_contacts(scene, geo)
      type(plot_scene_t), intent(inout) :: scene
      type(geometry_t), intent(in) :: geo
      integer(ip) :: c
      real(wp) :: h
      h = 0.01_wp*max(scene%window(2) - scene%window(1), scene%window(4) - scene%window(3))
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         associate (x => geo%contacts%x(c), y => geo%contacts%y(c), &
                    nx => geo%contacts%nx(c), ny => geo%contacts%ny(c))
            call scene%world_polyline(item_polyline, [x - h*nx, x + h*nx], &
                                      [y - h*ny, y + h*ny], dark_green, 2.0_wp)
         end associate
      end do
      call scene%add_legend(legend_line, 'contact normals ('// &
                            itoa(count(geo%contacts%live(1:geo%contacts%n)))//')', &
                            colour=dark_green, width=2.0_wp)
   end subroutine layer_contacts

   !> Domains (voids between blocks): the polygon through their contacts,
   !> with the domain id at its centre; the outer region is left out.
   subroutine layer_domains(scene, geo)
      type(plot_scene_t), intent(inout) :: scene
      type(geometry_t), intent(in) :: geo
      integer(ip) :: d, k, c, count
      real(wp), allocatable :: x(:), y(:)
      real(wp) :: px, py
      count = 0
      do d = 1, geo%domains%n
         if (.not. geo%domains%live(d)) cycle
         if (geo%domains%outer(d)) cycle
         if (geo%domains%count(d) < 1) cycle
         allocate (x(geo%domains%count(d)), y(geo%domains%count(d)))
         do k = 1, geo%domains%count(d)
            c = geo%domains%ring(geo%domains%first(d) + k - 1)
            x(k) = geo%contacts%x(c)
            y(k) = geo%contacts%y(c)
         end do
         if (size(x) >= 2) call scene%world_polyline(item_polygon, x, y, cyan, 1.5_wp)
         call scene%to_page(sum(x)/size(x), sum(y)/size(y), px, py)
         call scene%text(itoa(d), px + 4.0_wp, py + 4.0_wp, 9.0_wp, cyan, clip=.true.)
         deallocate (x, y)
         count = count + 1
      end do
      call scene%add_legend(legend_line, 'domains ('//itoa(count)//')', colour=cyan, &
                            width=1.5_wp)
   end subroutine layer_domains

   !> Velocity vectors at the centroids of rigid blocks (manual Fig. 2-2)
   !> and at the gridpoints of zoned (FDEF) blocks.
   subroutine layer_velocity(scene, geo, opts)
      type(plot_scene_t), intent(inout) :: scene
      type(geometry_t), intent(in) :: geo
      type(layer_options_t), intent(in) :: opts
      type(arrow_set_t) :: arrows
      integer(ip) :: b
      call arrows_reserve(arrows, geo%blocks%n + geo%gridpoints%n)
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         if (geo%blocks%nzone(b) > 0) then     ! a zoned block: its gridpoints
            call arrows_add_gridpoints(arrows, geo, geo%gridpoints%vx, geo%gridpoints%vy, &
                                       geo%blocks%gfirst(b), geo%blocks%gfirst(b) + geo%blocks%ngp(b) - 1)
         else
            call arrows_push(arrows, geo%blocks%xc(b), geo%blocks%yc(b), geo%blocks%vx(b), &
                             geo%blocks%vy(b))
         end if
      end do
      call draw_vectors(scene, arrows, opts, red, 'velocity vectors')
   end subroutine layer_velocity

   !> Displacement vectors at the corners of rigid blocks (their
   !> "gridpoints" in the manual's DISP keyword) and at the gridpoints of
   !> zoned (FDEF) blocks (whose corners are gridpoints too).
   subroutine layer_displacement(scene, geo, opts)
      type(plot_scene_t), intent(inout) :: scene
      type(geometry_t), intent(in) :: geo
      type(layer_options_t), intent(in) :: opts
      type(arrow_set_t) :: arrows
      integer(ip) :: c
      call arrows_reserve(arrows, geo%corners%n + geo%gridpoints%n)
      do c = 1, geo%corners%n
         if (.not. geo%corners%live(c)) cycle
         if (.not. geo%blocks%live(geo%corners%block(c))) cycle
         if (geo%corners%gp(c) > 0) cycle      ! drawn with the gridpoints
         call arrows_push(arrows, geo%corners%x(c), geo%corners%y(c), geo%corners%ux(c), &
                          geo%corners%uy(c))
      end do
      call arrows_add_gridpoints(arrows, geo, geo%gridpoints%ux, geo%gridpoints%uy)
      call draw_vectors(scene, arrows, opts, blue, 'displacement vectors')
   end subroutine layer_displacement

   !> Room for m arrows, none yet.
   pure subroutine arrows_reserve(arrows, m)
      type(arrow_set_t), intent(inout) :: arrows
      integer(ip), intent(in) :: m
      arrows%n = 0
      allocate (arrows%x(m), arrows%y(m), arrows%u(m), arrows%v(m))
   end subroutine arrows_reserve

   !> One more arrow: (pu, pv) at (px, py).
   pure subroutine arrows_push(arrows, px, py, pu, pv)
      type(arrow_set_t), intent(inout) :: arrows
      real(wp), intent(in) :: px, py, pu, pv
      arrows%n = arrows%n + 1
      arrows%x(arrows%n) = px
      arrows%y(arrows%n) = py
      arrows%u(arrows%n) = pu
      arrows%v(arrows%n) = pv
   end subroutine arrows_push

   !> One arrow (gu, gv) at each live gridpoint (of first..last when given):
   !> the arrows of VELOCITY, DISPLACEMENT and GPFORCES.
   pure subroutine arrows_add_gridpoints(arrows, geo, gu, gv, first, last)
      type(arrow_set_t), intent(inout) :: arrows
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: gu(:), gv(:)
      integer(ip), intent(in), optional :: first, last
      integer(ip) :: g, g1, g2
      g1 = 1
      g2 = geo%gridpoints%n
      if (present(first)) g1 = first
      if (present(last)) g2 = last
      do g = g1, g2
         if (.not. geo%gridpoints%live(g)) cycle
         call arrows_push(arrows, geo%gridpoints%x(g), geo%gridpoints%y(g), gu(g), gv(g))
      end do
   end subroutine arrows_add_gridpoints

   !> Arrows of (u, v) at (x, y). Window length = magnitude * sc; without
   !> <sc> the largest vector is 5% of the larger window side (manual 4.6).
   !> The legend shows the maximum and an arrow of a round magnitude.
   subroutine draw_vectors(scene, arrows, opts, colour, title)
      type(plot_scene_t), intent(inout) :: scene
      type(arrow_set_t), intent(in) :: arrows
      type(layer_options_t), intent(in) :: opts
      real(wp), intent(in) :: colour(3)
      character(len=*), intent(in) :: title
      real(wp) :: vmax, sc, px1, py1, px2, py2, wsize, ref
      integer :: i, nx, ny, cell, nonzero, ndrawn
      integer, allocatable :: best(:)
      !> page points per vector cell: about one arrow per finger's width
      real(wp), parameter :: vector_cell = 14.0_wp
      call scene%add_legend(legend_title, title, colour=colour)
      associate (x => arrows%x(1:arrows%n), y => arrows%y(1:arrows%n), &
                 u => arrows%u(1:arrows%n), v => arrows%v(1:arrows%n))
         vmax = 0.0_wp
         do i = 1, size(x)
            vmax = max(vmax, hypot(u(i), v(i)))
         end do
         wsize = max(scene%window(2) - scene%window(1), scene%window(4) - scene%window(3))
         if (opts%has_scale) then
            sc = opts%scale
         else if (vmax > 0.0_wp) then
            sc = vector_fraction*wsize/vmax
         else
            sc = 0.0_wp
         end if
         call scene%add_legend(legend_text, 'maximum = '//format_number(vmax))
         if (vmax <= 0.0_wp .or. sc <= 0.0_wp) then
            call scene%add_legend(legend_text, '(all vectors are zero)')
            return
         end if
         ! thinned to a readable density: in each cell of vector_cell points
         ! of the page, only the largest vector is drawn
         nx = max(1, ceiling((scene%vx1 - scene%vx0)/vector_cell))
         ny = max(1, ceiling((scene%vy1 - scene%vy0)/vector_cell))
         allocate (best(nx*ny))
         best = 0
         nonzero = 0
         do i = 1, size(x)
            if (u(i) == 0.0_wp .and. v(i) == 0.0_wp) cycle
            call scene%to_page(x(i), y(i), px1, py1)
            if (px1 < scene%vx0 .or. px1 > scene%vx1 .or. py1 < scene%vy0 .or. py1 > scene%vy1) cycle
            nonzero = nonzero + 1
            cell = 1 + min(nx - 1, int((px1 - scene%vx0)/vector_cell)) + &
                   nx*min(ny - 1, int((py1 - scene%vy0)/vector_cell))
            if (best(cell) == 0) then
               best(cell) = i
            else if (hypot(u(i), v(i)) > hypot(u(best(cell)), v(best(cell)))) then
               best(cell) = i
            end if
         end do
         ndrawn = 0
         do cell = 1, nx*ny
            i = best(cell)
            if (i == 0) cycle
            ndrawn = ndrawn + 1
            call scene%to_page(x(i), y(i), px1, py1)
            call scene%to_page(x(i) + sc*u(i), y(i) + sc*v(i), px2, py2)
            call scene%arrow(px1, py1, px2, py2, colour, 1.6_wp, .true.)
         end do
         if (ndrawn < nonzero) call scene%add_legend(legend_text, itoa(ndrawn)//' of '// &
                                                     itoa(nonzero)//' shown (largest per cell)')
         ! a round magnitude whose arrow fits the legend panel
         ref = nice_number(vmax)
         do while (scene%world_length(sc*ref) > 150.0_wp)
            ref = nice_number(0.99_wp*ref)
         end do
         call scene%add_legend(legend_arrow, format_number(ref), colour=colour, &
                               length=scene%world_length(sc*ref))
      end associate
   end subroutine draw_vectors

   !> SHEAR (|us|) or CLOSURE (un) as line thickness along each contact.
   !> Thickness = thick_max * value / reference, the reference being <sc>
   !> or the largest value (manual 4.6).
   subroutine layer_joint_thickness(scene, geo, opts, shear)
      type(plot_scene_t), intent(inout) :: scene
      type(geometry_t), intent(in) :: geo
      type(layer_options_t), intent(in) :: opts
      logical, intent(in) :: shear
      integer(ip) :: c
      real(wp) :: vmax, ref, val, w
      real(wp) :: colour(3)
      vmax = 0.0_wp
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         if (shear) then
            vmax = max(vmax, abs(geo%contacts%state%us(c)))
         else
            vmax = max(vmax, abs(geo%contacts%state%un(c)))
         end if
      end do
      ref = vmax
      if (opts%has_scale) ref = opts%scale
      if (shear) then
         ! purple: red is SLIP's 'at slip', orange its 'open' (both layers
         ! are often drawn together)
         call scene%add_legend(legend_title, 'joint shear displacement', colour=purple)
      else
         call scene%add_legend(legend_title, 'joint closure / opening')
      end if
      call scene%add_legend(legend_text, 'maximum = '//format_number(vmax))
      if (ref <= 0.0_wp) then
         call scene%add_legend(legend_text, '(all values are zero)')
         return
      end if
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         if (shear) then
            val = abs(geo%contacts%state%us(c))
            colour = purple
         else
            val = geo%contacts%state%un(c)
            colour = merge(red, blue, val > 0.0_wp)
            val = abs(val)
         end if
         if (val <= 0.0_wp) cycle
         w = max(0.5_wp, min(3.0_wp*thick_max, thick_max*val/ref))
         call contact_segment(scene, geo, c, colour, w)
      end do
      if (shear) then
         call scene%add_legend(legend_line, '= '//format_number(ref), colour=purple, &
                               width=thick_max)
      else
         call scene%add_legend(legend_line, 'closure '//format_number(ref), colour=blue, &
                               width=thick_max)
         call scene%add_legend(legend_line, 'opening '//format_number(ref), colour=red, &
                               width=thick_max)
      end if
   end subroutine layer_joint_thickness

   !> Contacts at the friction limit (slip) and open in tension.
   subroutine layer_slip(scene, geo)
      type(plot_scene_t), intent(inout) :: scene
      type(geometry_t), intent(in) :: geo
      integer(ip) :: c, nslip, nopen
      real(wp) :: colour(3)
      nslip = 0
      nopen = 0
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         if (iand(geo%contacts%state%flags(c), plot_contact_tension) /= 0) then
            colour = orange
            nopen = nopen + 1
         else if (iand(geo%contacts%state%flags(c), plot_contact_slip) /= 0) then
            colour = red
            nslip = nslip + 1
         else
            cycle
         end if
         call contact_segment(scene, geo, c, colour, 4.0_wp)
      end do
      call scene%add_legend(legend_title, 'joint state')
      call scene%add_legend(legend_line, 'at slip ('//itoa(nslip)//')', colour=red, &
                            width=4.0_wp)
      call scene%add_legend(legend_line, 'open ('//itoa(nopen)//')', colour=orange, &
                            width=4.0_wp)
   end subroutine layer_slip

   !> Joints (JCONS 5) whose fracture flag is set (manual 4.6 FRACTURES): a
   !> thick segment along each such contact, its count in the legend.
   subroutine layer_fractures(scene, geo)
      type(plot_scene_t), intent(inout) :: scene
      type(geometry_t), intent(in) :: geo
      integer(ip) :: c, n
      n = 0
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         if (iand(geo%contacts%state%flags(c), plot_contact_fractured) == 0) cycle
         n = n + 1
         call contact_segment(scene, geo, c, magenta, 4.0_wp)
      end do
      call scene%add_legend(legend_line, 'fractured joints, JCONS 5 ('//itoa(n)//')', &
                            colour=magenta, width=4.0_wp)
   end subroutine layer_fractures

   !> PLOT STRUCT (manual 4.6, "structural element geometry"): the beam
   !> elements as thick lines between their nodes, a small square at each node
   !> (lumped mass), and each interface as a thin line from its node to the
   !> contact point on the block edge (open interfaces, un > 0, in red).
   subroutine layer_structures(scene, model)
      type(plot_scene_t), intent(inout) :: scene
      type(model_t), intent(in) :: model
      integer(ip) :: e, k, i, nel, nnode, nopen
      real(wp) :: h
      nel = 0
      nnode = 0
      nopen = 0
      if (allocated(model%structures)) then
         h = 0.004_wp*max(scene%window(2) - scene%window(1), scene%window(4) - scene%window(3))
         associate (nd => model%structures%nodes, el => model%structures%elements, &
                    it => model%structures%interfaces)
            do e = 1, el%n
               call scene%world_polyline(item_polyline, [nd%x(el%n1(e)), nd%x(el%n2(e))], &
                                         [nd%y(el%n1(e)), nd%y(el%n2(e))], purple, 3.0_wp)
            end do
            nel = el%n
            do k = 1, nd%n
               call scene%world_polyline(item_polygon, &
                                         [nd%x(k) - h, nd%x(k) + h, nd%x(k) + h, nd%x(k) - h], &
                                         [nd%y(k) - h, nd%y(k) - h, nd%y(k) + h, nd%y(k) + h], &
                                         black, 1.0_wp)
            end do
            nnode = nd%n
            do i = 1, it%n
               k = it%node(i)
               if (it%un(i) > 0.0_wp) then
                  nopen = nopen + 1
                  call scene%world_polyline(item_polyline, [nd%x(k), it%x(i)], [nd%y(k), it%y(i)], &
                                            red, 1.0_wp)
               else
                  call scene%world_polyline(item_polyline, [nd%x(k), it%x(i)], [nd%y(k), it%y(i)], &
                                            dark_green, 1.0_wp)
               end if
            end do
         end associate
      end if
      call scene%add_legend(legend_line, 'structural elements ('//itoa(nel)//')', &
                            colour=purple, width=3.0_wp)
      call scene%add_legend(legend_text, 'lumped masses ('//itoa(nnode)//')')
      if (nopen > 0) call scene%add_legend(legend_line, 'open interfaces ('//itoa(nopen)//')', &
                                           colour=red, width=1.0_wp)
   end subroutine layer_structures

   !> PLOT CABLE (cable elements and nodes, in the steel's material colour),
   !> REINFORCE (local reinforcement: a short bar along the bolt axis across
   !> each joint it crosses), AXIAL <sc> (reinforcement) and CFORCE <sc>
   !> (cables): the axial force as the line thickness, tension red and
   !> compression blue; <sc> is the force drawn at the thickest line (else
   !> the largest force).
   subroutine layer_reinforcement(scene, model, name, opts)
      type(plot_scene_t), intent(inout) :: scene
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: name
      type(layer_options_t), intent(in) :: opts
      integer(ip) :: i, n
      integer(ip), allocatable :: mat(:)
      real(wp), allocatable :: xa(:), ya(:), xb(:), yb(:), f(:)
      real(wp) :: h, ref, w
      n = 0
      ref = 0.0_wp
      h = 0.03_wp*max(scene%window(2) - scene%window(1), scene%window(4) - scene%window(3))
      if (allocated(model%reinforcement)) then
         ! one segment per item: a cable element from node to node, or a
         ! bar of 2h along the bolt axis centred where it crosses the joint
         associate (r => model%reinforcement%reinf, nd => model%reinforcement%nodes, &
                    el => model%reinforcement%elements)
            select case (name)
            case ('CABLE', 'CFORCE')
               n = el%n
               xa = nd%x(el%n1(1:n)); ya = nd%y(el%n1(1:n))
               xb = nd%x(el%n2(1:n)); yb = nd%y(el%n2(1:n))
               f = el%axial(1:n)
               mat = int(el%mats(1:n), ip)
            case default
               n = r%n
               xa = 0.5_wp*(r%x1(1:n) + r%x2(1:n)) - h*r%ax(1:n)
               ya = 0.5_wp*(r%y1(1:n) + r%y2(1:n)) - h*r%ay(1:n)
               xb = 0.5_wp*(r%x1(1:n) + r%x2(1:n)) + h*r%ax(1:n)
               yb = 0.5_wp*(r%y1(1:n) + r%y2(1:n)) + h*r%ay(1:n)
               f = r%fa(1:n)
               mat = r%material(1:n)
            end select
         end associate
         select case (name)
         case ('CABLE', 'REINFORCE')
            w = merge(2.0_wp, 3.0_wp, name == 'CABLE')
            do i = 1, n
               call scene%world_polyline(item_polyline, [xa(i), xb(i)], [ya(i), yb(i)], &
                                         material_colour(int(mat(i))), w)
            end do
         case default
            if (n > 0) ref = maxval(abs(f))
            if (opts%has_scale) ref = opts%scale
            do i = 1, n
               if (ref <= 0.0_wp) exit
               w = max(0.5_wp, thick_max*min(1.0_wp, abs(f(i))/ref))
               call scene%world_polyline(item_polyline, [xa(i), xb(i)], [ya(i), yb(i)], &
                                         merge(red, blue, f(i) >= 0.0_wp), w)
            end do
         end select
      end if
      select case (name)
      case ('CABLE')
         call scene%add_legend(legend_line, 'cable elements ('//itoa(n)//')', colour=orange, &
                               width=2.0_wp)
      case ('REINFORCE')
         call scene%add_legend(legend_line, 'reinforcement across joints ('//itoa(n)//')', &
                               colour=orange, width=3.0_wp)
      case default
         call scene%add_legend(legend_title, trim(merge('cable axial force        ', &
                                                   'reinforcement axial force', name == 'CFORCE')))
         call scene%add_legend(legend_line, 'tension '//format_number(ref), colour=red, &
                               width=thick_max)
         call scene%add_legend(legend_line, 'compression '//format_number(ref), colour=blue, &
                               width=thick_max)
      end select
   end subroutine layer_reinforcement

   !> A segment of line width `width` along contact c (its length, or the
   !> rounding length for a point contact), for the joint layers.
   subroutine contact_segment(scene, geo, c, colour, width)
      type(plot_scene_t), intent(inout) :: scene
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: c
      real(wp), intent(in) :: colour(3), width
      real(wp) :: h, tx, ty
      h = 0.5_wp*geo%contacts%length(c)
      if (h <= 0.0_wp) h = 0.5_wp*geo%round
      tx = -geo%contacts%ny(c)
      ty = geo%contacts%nx(c)
      call scene%world_polyline(item_polyline, &
                                [geo%contacts%x(c) - h*tx, geo%contacts%x(c) + h*tx], &
                                [geo%contacts%y(c) - h*ty, geo%contacts%y(c) + h*ty], &
                                colour, width)
   end subroutine contact_segment

   !> The window frame with its coordinates along the bottom and left.
   subroutine layer_window(scene)
      type(plot_scene_t), intent(inout) :: scene
      real(wp) :: step, v, px, py
      integer :: k
      call scene%polyline(item_polygon, [scene%vx0, scene%vx1, scene%vx1, scene%vx0], &
                          [scene%vy0, scene%vy0, scene%vy1, scene%vy1], black, 2.0_wp)
      step = nice_number(max(scene%window(2) - scene%window(1), &
                             scene%window(4) - scene%window(3))/5.0_wp)
      if (step <= 0.0_wp) return
      if (maxval(abs(scene%window)) > 1.0e6_wp*step) return   ! ticks would not resolve
      do k = ceiling(scene%window(1)/step), floor(scene%window(2)/step)
         v = real(k, wp)*step
         call scene%to_page(v, scene%window(3), px, py)
         call scene%polyline(item_polyline, [px, px], [py, py + 8.0_wp], black, 1.5_wp)
         call scene%text(format_tick(v), px, py + 12.0_wp, 10.0_wp, black, align=align_centre)
      end do
      do k = ceiling(scene%window(3)/step), floor(scene%window(4)/step)
         v = real(k, wp)*step
         call scene%to_page(scene%window(1), v, px, py)
         call scene%polyline(item_polyline, [px, px + 8.0_wp], [py, py], black, 1.5_wp)
         call scene%text(format_tick(v), px + 12.0_wp, py - 5.0_wp, 10.0_wp, black)
      end do
      call scene%add_legend(legend_text, 'window frame')
   end subroutine layer_window


   ! ---- bins of block bounding boxes for point-in-block queries ----

   subroutine bins_build(geo, bins)
      type(geometry_t), intent(in) :: geo
      type(bins_t), intent(out) :: bins
      integer(ip) :: b
      integer :: nlive, i, j, k
      real(wp) :: xmin, xmax, ymin, ymax
      integer, allocatable :: fill(:)
      nlive = 0
      xmin = huge(1.0_wp); xmax = -huge(1.0_wp); ymin = huge(1.0_wp); ymax = -huge(1.0_wp)
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         nlive = nlive + 1
         xmin = min(xmin, geo%blocks%xmin(b)); xmax = max(xmax, geo%blocks%xmax(b))
         ymin = min(ymin, geo%blocks%ymin(b)); ymax = max(ymax, geo%blocks%ymax(b))
      end do
      if (nlive == 0) then
         allocate (bins%start(2), bins%list(0))
         bins%start = 1
         return
      end if
      bins%h = max(xmax - xmin, ymax - ymin)/max(1.0_wp, sqrt(real(nlive, wp)))
      if (bins%h <= 0.0_wp) bins%h = 1.0_wp
      bins%x0 = xmin - bins%h
      bins%y0 = ymin - bins%h
      bins%nx = int((xmax - bins%x0)/bins%h) + 2
      bins%ny = int((ymax - bins%y0)/bins%h) + 2
      allocate (bins%start(bins%nx*bins%ny + 1), fill(bins%nx*bins%ny))
      bins%start = 0
      call walk(.false.)
      call counts_to_starts(bins%start)
      allocate (bins%list(bins%start(bins%nx*bins%ny + 1) - 1))
      fill = 0
      call walk(.true.)
   contains
      pure integer function cell(v, v0)
         real(wp), intent(in) :: v, v0
         cell = int((v - v0)/bins%h) + 1
      end function cell

      !> Each live block in each cell its bounding box covers: counted
      !> (bins%start(k + 1), the size of cell k) or placed in the cell's slots.
      subroutine walk(place)
         logical, intent(in) :: place
         do b = 1, geo%blocks%n
            if (.not. geo%blocks%live(b)) cycle
            do j = cell(geo%blocks%ymin(b), bins%y0), cell(geo%blocks%ymax(b), bins%y0)
               do i = cell(geo%blocks%xmin(b), bins%x0), cell(geo%blocks%xmax(b), bins%x0)
                  k = i + (j - 1)*bins%nx
                  if (place) then
                     bins%list(bins%start(k) + fill(k)) = b
                     fill(k) = fill(k) + 1
                  else
                     bins%start(k + 1) = bins%start(k + 1) + 1
                  end if
               end do
            end do
         end do
      end subroutine walk
   end subroutine bins_build

   !> Is (x, y) inside a live block other than `self`?
   logical function inside_other(geo, bins, self, x, y) result(inside)
      type(geometry_t), intent(in) :: geo
      type(bins_t), intent(in) :: bins
      integer(ip), intent(in) :: self
      real(wp), intent(in) :: x, y
      integer :: i, j, k, m
      integer(ip) :: b
      inside = .false.
      i = int((x - bins%x0)/bins%h) + 1
      j = int((y - bins%y0)/bins%h) + 1
      if (i < 1 .or. j < 1 .or. i > bins%nx .or. j > bins%ny) return
      k = i + (j - 1)*bins%nx
      do m = bins%start(k), bins%start(k + 1) - 1
         b = bins%list(m)
         if (b == self) cycle
         if (x < geo%blocks%xmin(b) .or. x > geo%blocks%xmax(b)) cycle
         if (y < geo%blocks%ymin(b) .or. y > geo%blocks%ymax(b)) cycle
         inside = block_contains_point(geo, b, x, y)
         if (inside) return
      end do
   end function inside_other

end module plot_layers
