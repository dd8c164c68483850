!> PLOT layers of UDEC manual (ICG1.5, 1989) Section 4.6 that read along a
!> line or show a field the other modules do not: JLINE and JOINT (joint
!> profiles), ROTATE BLOCK / ZONE, GPFORCES, DSH.
!>
!> JLINE x1 y1 x2 y2 q: every joint the segment crosses, sampled where it
!> crosses it (the contact whose stretch of joint holds the crossing).
!> JOINT x1 y1 x2 y2 q <tolc>: the contacts of the joint within tolc of the
!> segment (default: the rounding length, as PRINT JOINT), in order along it.
!> q is APE, FLOW, NSTR, PP, SSTR, VEL (manual), NDIS, SDIS (udec), or a
!> contact offset koff of Section 6.1 (model_address). A profile is drawn on
!> the model: the segment is its base line and each value is an offset
!> perpendicular to it (positive to the left of x1,y1 -> x2,y2), the
!> largest 15 % of the window; the points are joined in order, each tied to
!> the base by a thin line. The legend gives the range and a scale bar.
!>
!> ROTATE BLOCK fills each block by its rotation (rigid: the accumulated
!> rotation of the block; zoned: the area-weighted mean of its zones');
!> ROTATE ZONE fills each zone by its rotation 0.5 (d uy/dx - d ux/dy) of
!> the accumulated gridpoint displacements (linear in the triangle), in
!> degrees, counter-clockwise positive, with a colour bar.
!> GPFORCES <sc>: the force sum of each gridpoint in the last step (its
!> unbalanced force), as vectors. DSH: at each contact with a shear
!> displacement us, a short arrow along the joint giving its sense (along the
!> contact tangent (-ny, nx) when us > 0, against it when us < 0).
module plot_profiles
   use core_kinds, only: wp, ip
   use core_strings, only: table_text, text_pair_t
   use core_sort, only: sort_order
   use core_constants, only: pi
   use core_error, only: error_t, set_error
   use core_output, only: itoa
   use model_state, only: model_t
   use model_geometry, only: geometry_t
   use model_address, only: address_field, ak_contact
   use model_zone_fields, only: any_zones, zone_area
   use plot_scene, only: plot_scene_t, item_polyline, item_fill, item_polygon, legend_text, &
                         legend_line, legend_title, legend_bar, black, grey, red, blue, &
                         dark_green, purple, format_number, nice_number
   use plot_layers, only: layer_options_t, draw_vectors, plot_block_outline, arrow_set_t, &
                          arrows_reserve, arrows_add_gridpoints
   use plot_zones, only: band_colour, contour_levels
   use plot_fluid, only: plot_contact_pressures
   implicit none
   private
   public :: plot_profile_layer, plot_profile_names, profile_quantity_name
   public :: joint_profile_points, zone_rotation

   !> Layers this module draws (canonical PLOT keyword names).
   character(len=16), parameter :: plot_profile_names(5) = [character(len=16) :: &
      'JLINE', 'JOINT', 'ROTATE', 'GPFORCES', 'DSH']
   !> The largest profile offset, as a fraction of the larger window side.
   real(wp), parameter :: profile_fraction = 0.15_wp

   !> Legend titles of the profile quantities, with their units.
   type(text_pair_t), parameter :: quantity_titles(*) = [ &
      text_pair_t('APE', 'hydraulic aperture (m)'), &
      text_pair_t('FLOW', 'flow rate (m2/s)'), &
      text_pair_t('NSTR', 'normal stress (Pa; compr. +)'), &
      text_pair_t('PP', 'fluid pressure (Pa)'), &
      text_pair_t('SSTR', 'shear stress (Pa)'), &
      text_pair_t('VEL', 'fluid velocity (m/s)'), &
      text_pair_t('NDIS', 'normal displacement (m)'), &
      text_pair_t('SDIS', 'shear displacement (m)')]

contains

   !> Canonical quantity of a JLINE / JOINT keyword (manual: Ape, Flow, NStr,
   !> PP, SStr, Vel; udec adds NDis, SDis), '' if `token` names none. A
   !> number is a contact offset koff (returned as 'KOFF').
   function profile_quantity_name(token) result(name)
      character(len=*), intent(in) :: token
      character(len=:), allocatable :: name
      character(len=8), parameter :: names(8) = [character(len=8) :: 'APE', 'FLOW', 'NSTR', &
                                                 'PP', 'SSTR', 'VEL', 'NDIS', 'SDIS']
      integer, parameter :: min_len(8) = [1, 1, 2, 2, 2, 1, 2, 2]
      integer :: i, n
      name = ''
      n = len_trim(token)
      if (n == 0) return
      if (verify(token(1:n), '0123456789') == 0) then
         name = 'KOFF'
         return
      end if
      do i = 1, size(names)
         if (n >= min_len(i) .and. n <= len_trim(names(i))) then
            if (names(i)(1:n) == token(1:n)) then
               name = trim(names(i))
               return
            end if
         end if
      end do
   end function profile_quantity_name

   !> Value of quantity `what` at contact c (`ok` false when there is none).
   subroutine contact_value(model, what, koff, pp, c, v, ok)
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: what
      integer, intent(in) :: koff
      real(wp), intent(in) :: pp(:)
      integer(ip), intent(in) :: c
      real(wp), intent(out) :: v
      logical, intent(out) :: ok
      character(len=:), allocatable :: field
      real(wp) :: l
      ok = .true.
      v = 0.0_wp
      associate (ct => model%geometry%contacts)
         l = ct%length(c)
         select case (what)
         case ('NSTR')
            ! compression positive (manual 4.1), as HISTORY NSTR, PRINT CONTACT
            if (l > 0.0_wp) v = ct%state%fn(c)/l
         case ('SSTR')
            if (l > 0.0_wp) v = ct%state%fs(c)/l
         case ('NDIS')
            v = ct%state%un(c)
         case ('SDIS')
            v = ct%state%us(c)
         case ('APE', 'FLOW', 'VEL', 'PP')
            ok = .false.
            if (.not. allocated(model%fluid)) return
            if (c > model%fluid%nc) return
            ok = .true.
            select case (what)
            case ('APE')
               v = model%fluid%aperture(c)
            case ('FLOW')
               v = model%fluid%q(c)
            case ('VEL')
               if (model%fluid%aperture(c) > 0.0_wp) v = model%fluid%q(c)/model%fluid%aperture(c)
            case default
               v = pp(c)
            end select
         case default
            if (allocated(model%fluid)) then
               call address_field(model%geometry, ak_contact, c, int(koff, ip), field, v, ok, &
                                  model%fluid)
            else
               call address_field(model%geometry, ak_contact, c, int(koff, ip), field, v, ok)
            end if
         end select
      end associate
   end subroutine contact_value

   !> The contacts of a JLINE (`jline`) or JOINT profile along x1 y1 x2 y2,
   !> in order along the segment: ids, distance along it, and the point of
   !> each sample (the crossing for JLINE, the contact for JOINT).
   subroutine joint_profile_points(geo, jline, xy, tolc, ids, along, px, py, n)
      type(geometry_t), intent(in) :: geo
      logical, intent(in) :: jline
      real(wp), intent(in) :: xy(4), tolc
      integer(ip), allocatable, intent(out) :: ids(:)
      real(wp), allocatable, intent(out) :: along(:), px(:), py(:)
      integer, intent(out) :: n
      integer(ip) :: c
      integer(ip), allocatable :: perm(:)
      real(wp) :: dx, dy, seg, tx, ty, h, ex, ey, den, s, t, qx, qy, d, a
      allocate (ids(max(1_ip, geo%contacts%n)), along(max(1_ip, geo%contacts%n)), &
                px(max(1_ip, geo%contacts%n)), py(max(1_ip, geo%contacts%n)))
      n = 0
      dx = xy(3) - xy(1)
      dy = xy(4) - xy(2)
      seg = hypot(dx, dy)
      if (seg <= 0.0_wp) return
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         if (jline) then
            ! the stretch of joint the contact stands for: its length along
            ! the tangent (the rounding length for a point contact)
            h = 0.5_wp*geo%contacts%length(c)
            if (h <= 0.0_wp) h = 0.5_wp*geo%round
            tx = -geo%contacts%ny(c)
            ty = geo%contacts%nx(c)
            ex = geo%contacts%x(c) - h*tx
            ey = geo%contacts%y(c) - h*ty
            ! x1 + t (dx, dy) = e + s 2h (tx, ty)
            den = dx*(2.0_wp*h*ty) - dy*(2.0_wp*h*tx)
            if (abs(den) <= 1.0e-12_wp*seg*2.0_wp*h) cycle
            t = ((ex - xy(1))*(2.0_wp*h*ty) - (ey - xy(2))*(2.0_wp*h*tx))/den
            s = ((ex - xy(1))*dy - (ey - xy(2))*dx)/den
            if (t < 0.0_wp .or. t > 1.0_wp .or. s < 0.0_wp .or. s > 1.0_wp) cycle
            qx = xy(1) + t*dx
            qy = xy(2) + t*dy
            a = t*seg
         else
            t = ((geo%contacts%x(c) - xy(1))*dx + (geo%contacts%y(c) - xy(2))*dy)/(seg*seg)
            if (t < 0.0_wp .or. t > 1.0_wp) cycle
            qx = xy(1) + t*dx
            qy = xy(2) + t*dy
            d = hypot(geo%contacts%x(c) - qx, geo%contacts%y(c) - qy)
            if (d > tolc) cycle
            qx = geo%contacts%x(c)
            qy = geo%contacts%y(c)
            a = t*seg
         end if
         n = n + 1
         ids(n) = c
         along(n) = a
         px(n) = qx
         py(n) = qy
      end do
      ! by position along the segment (stable: equal positions keep the
      ! order of the contacts)
      allocate (perm(n))
      call sort_order(along(1:n), perm)
      ids(1:n) = ids(perm)
      along(1:n) = along(perm)
      px(1:n) = px(perm)
      py(1:n) = py(perm)
   end subroutine joint_profile_points

   !> Draw layer `name` (one of `plot_profile_names`): ROTATE, GPFORCES and
   !> DSH by their own routines; JLINE / JOINT, the profile of a joint
   !> quantity along the segment, here.
   subroutine plot_profile_layer(scene, model, name, opts, error)
      type(plot_scene_t), intent(inout) :: scene
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: name
      type(layer_options_t), intent(in) :: opts
      type(error_t), allocatable, intent(out) :: error
      integer(ip), allocatable :: ids(:)
      real(wp), allocatable :: along(:), px(:), py(:), val(:), pp(:), ox(:), oy(:)
      real(wp) :: tolc, dx, dy, seg, nx, ny, vmax, vmin, amax, k, wsize, ref, v
      integer :: n, i, m
      logical :: ok
      character(len=:), allocatable :: title
      select case (name)
      case ('ROTATE')
         call layer_rotation(scene, model, opts)
         return
      case ('GPFORCES')
         call layer_gpforces(scene, model%geometry, opts)
         return
      case ('DSH')
         call layer_shear_directions(scene, model%geometry)
         return
      end select
      associate (geo => model%geometry, xy => opts%profile_xy)
         tolc = geo%round
         if (opts%has_tolc) tolc = opts%tolc
         title = trim(name)//': '//quantity_title(opts%quantity, opts%koff)
         call scene%add_legend(legend_title, title, colour=purple)
         call scene%add_legend(legend_text, 'along ('//format_number(xy(1))//', '// &
                               format_number(xy(2))//') to ('//format_number(xy(3))//', '// &
                               format_number(xy(4))//')')
         call scene%world_polyline(item_polyline, [xy(1), xy(3)], [xy(2), xy(4)], grey, 1.2_wp)
         call joint_profile_points(geo, name == 'JLINE', xy, tolc, ids, along, px, py, n)
         if (n == 0) then
            if (name == 'JLINE') then
               call scene%add_legend(legend_text, '(the line crosses no joint)')
            else
               call scene%add_legend(legend_text, '(no contact within '//format_number(tolc)// &
                                     ' of the line)')
            end if
            return
         end if
         allocate (pp(max(1_ip, geo%contacts%n)))
         pp = 0.0_wp
         if (opts%quantity == 'PP' .and. allocated(model%fluid)) &
            call plot_contact_pressures(model%fluid, geo, min(geo%contacts%n, model%fluid%nc), pp)
         allocate (val(n))
         m = 0
         do i = 1, n
            call contact_value(model, trim(opts%quantity), opts%koff, pp, ids(i), v, ok)
            if (.not. ok) then
               if (opts%quantity == 'KOFF') then
                  call set_error(error, 'PLOT '//name//': contact offset '//itoa(opts%koff)// &
                                 ' names no field of a contact record (UDEC manual, ' // &
                                 'Section 6.1; PRINT CONTACT lists the contacts)')
                  return
               end if
               call scene%add_legend(legend_text, '(no fluid: give FLUID first)')
               return
            end if
            m = m + 1
            val(m) = v
         end do
         vmax = maxval(val(1:n))
         vmin = minval(val(1:n))
         call scene%add_legend(legend_text, itoa(n)//' point(s): minimum '// &
                               format_number(vmin)//', maximum '//format_number(vmax))
         amax = max(abs(vmax), abs(vmin))
         dx = xy(3) - xy(1)
         dy = xy(4) - xy(2)
         seg = hypot(dx, dy)
         nx = -dy/seg
         ny = dx/seg
         wsize = max(scene%window(2) - scene%window(1), scene%window(4) - scene%window(3))
         k = 0.0_wp
         if (amax > 0.0_wp) k = profile_fraction*wsize/amax
         allocate (ox(n), oy(n))
         do i = 1, n
            ! base point on the segment, offset along its left normal
            ox(i) = xy(1) + along(i)*dx/seg + k*val(i)*nx
            oy(i) = xy(2) + along(i)*dy/seg + k*val(i)*ny
            call scene%world_polyline(item_polyline, [xy(1) + along(i)*dx/seg, ox(i)], &
                                      [xy(2) + along(i)*dy/seg, oy(i)], purple, 0.6_wp)
         end do
         call scene%world_polyline(item_polyline, ox, oy, purple, 2.0_wp)
         do i = 1, n
            call scene%world_polyline(item_fill, ox(i) + 0.004_wp*wsize*[-1.0_wp, 1.0_wp, &
                                      1.0_wp, -1.0_wp], oy(i) + 0.004_wp*wsize*[-1.0_wp, &
                                      -1.0_wp, 1.0_wp, 1.0_wp], purple)
         end do
         if (amax > 0.0_wp) then
            ref = nice_number(amax)
            do while (scene%world_length(k*ref) > 60.0_wp)
               ref = nice_number(0.99_wp*ref)
            end do
            call scene%add_legend(legend_text, 'offset left of the line: positive;')
            call scene%add_legend(legend_text, format_number(ref)//' is drawn '// &
                                  format_number(k*ref)//' m long')
         else
            call scene%add_legend(legend_text, '(all values are zero)')
         end if
      end associate
   end subroutine plot_profile_layer

   !> Legend title of a profile quantity, with its unit.
   function quantity_title(q, koff) result(t)
      character(len=*), intent(in) :: q
      integer, intent(in) :: koff
      character(len=:), allocatable :: t
      t = table_text(quantity_titles, q, 'contact offset '//itoa(koff))
   end function quantity_title

   !> Rotation of zone z, degrees counter-clockwise: 0.5 (d uy/dx - d ux/dy)
   !> of the accumulated gridpoint displacements, linear in the triangle.
   pure real(wp) function zone_rotation(geo, z) result(w)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: z
      real(wp) :: x(3), y(3), ux(3), uy(3), a2, duydx, duxdy
      integer(ip) :: g(3)
      g = [geo%zones%g1(z), geo%zones%g2(z), geo%zones%g3(z)]
      x = geo%gridpoints%x(g)
      y = geo%gridpoints%y(g)
      ux = geo%gridpoints%ux(g)
      uy = geo%gridpoints%uy(g)
      a2 = (x(2) - x(1))*(y(3) - y(1)) - (x(3) - x(1))*(y(2) - y(1))
      w = 0.0_wp
      if (a2 == 0.0_wp) return
      ! gradient of a linear field f: df/dx = sum f_i (y_j - y_k) / 2A
      duydx = (uy(1)*(y(2) - y(3)) + uy(2)*(y(3) - y(1)) + uy(3)*(y(1) - y(2)))/a2
      duxdy = (ux(1)*(x(3) - x(2)) + ux(2)*(x(1) - x(3)) + ux(3)*(x(2) - x(1)))/a2
      w = 0.5_wp*(duydx - duxdy)*180.0_wp/pi
   end function zone_rotation

   !> ROTATE BLOCK | ZONE: blocks or zones filled by their rotation.
   subroutine layer_rotation(scene, model, opts)
      type(plot_scene_t), intent(inout) :: scene
      type(model_t), intent(in) :: model
      type(layer_options_t), intent(in) :: opts
      real(wp), allocatable :: val(:), edges(:), x(:), y(:), asum(:)
      real(wp) :: fmin, fmax, interval, a, zx(3), zy(3)
      integer(ip) :: b, z, nent
      integer :: k, nb, n
      logical :: zones
      zones = opts%quantity == 'ZONE'
      associate (geo => model%geometry)
         if (zones) then
            call scene%add_legend(legend_title, 'zone rotation (degrees, ccw +)')
            if (.not. any_zones(geo)) then
               call scene%add_legend(legend_text, '(no zones: GENERATE the FDEF blocks)')
               return
            end if
            nent = geo%zones%n
            allocate (val(max(1_ip, nent)))
            val = 0.0_wp
            do z = 1, nent
               if (geo%zones%live(z)) val(z) = zone_rotation(geo, z)
            end do
         else
            call scene%add_legend(legend_title, 'block rotation (degrees, ccw +)')
            nent = geo%blocks%n
            allocate (val(max(1_ip, nent)), asum(max(1_ip, nent)))
            val = 0.0_wp
            asum = 0.0_wp
            do b = 1, nent
               if (geo%blocks%live(b)) val(b) = geo%blocks%rot(b)*180.0_wp/pi
            end do
            ! a zoned block turns with its zones: their area-weighted mean
            do z = 1, geo%zones%n
               if (.not. geo%zones%live(z)) cycle
               b = geo%zones%block(z)
               if (asum(b) == 0.0_wp) val(b) = 0.0_wp
               a = zone_area(geo, z)
               val(b) = val(b) + a*zone_rotation(geo, z)
               asum(b) = asum(b) + a
            end do
            do b = 1, nent
               if (asum(b) > 0.0_wp) val(b) = val(b)/asum(b)
            end do
         end if
         fmin = huge(1.0_wp)
         fmax = -huge(1.0_wp)
         do k = 1, int(nent)
            if (zones) then
               if (.not. geo%zones%live(k)) cycle
            else
               if (.not. geo%blocks%live(k)) cycle
            end if
            fmin = min(fmin, val(k))
            fmax = max(fmax, val(k))
         end do
         if (fmin > fmax) then
            call scene%add_legend(legend_text, '(nothing to plot)')
            return
         end if
         call contour_levels(fmin, fmax, opts, edges, interval)
         nb = size(edges) - 1
         call scene%add_legend(legend_text, 'minimum '//format_number(fmin)//', maximum '// &
                               format_number(fmax))
         do k = 1, int(nent)
            if (zones) then
               if (.not. geo%zones%live(k)) cycle
               zx = geo%gridpoints%x([geo%zones%g1(k), geo%zones%g2(k), geo%zones%g3(k)])
               zy = geo%gridpoints%y([geo%zones%g1(k), geo%zones%g2(k), geo%zones%g3(k)])
               call scene%world_polyline(item_fill, zx, zy, band_colour(band_of(val(k)), nb))
            else
               if (.not. geo%blocks%live(k)) cycle
               call plot_block_outline(geo, int(k, ip), .not. opts%nc, x, y, n)
               call scene%world_polyline(item_fill, x(1:n), y(1:n), &
                                         band_colour(band_of(val(k)), nb))
               call scene%world_polyline(item_polygon, x(1:n), y(1:n), grey, 0.8_wp)
            end if
         end do
         do k = nb, 1, -1
            call scene%add_legend(legend_bar, format_number(edges(k + 1)), &
                                  colour=band_colour(k, nb), low=format_number(edges(k)))
         end do
      end associate
   contains
      integer function band_of(v) result(kb)
         real(wp), intent(in) :: v
         kb = 1
         do while (kb < nb)
            if (v < edges(kb + 1)) exit
            kb = kb + 1
         end do
      end function band_of
   end subroutine layer_rotation

   !> GPFORCES <sc>: the force sum of each live gridpoint in the last step.
   subroutine layer_gpforces(scene, geo, opts)
      type(plot_scene_t), intent(inout) :: scene
      type(geometry_t), intent(in) :: geo
      type(layer_options_t), intent(in) :: opts
      type(arrow_set_t) :: arrows
      if (.not. any_zones(geo)) then
         call scene%add_legend(legend_title, 'gridpoint forces (N)')
         call scene%add_legend(legend_text, '(no zones: GENERATE the FDEF blocks)')
         return
      end if
      call arrows_reserve(arrows, geo%gridpoints%n)
      call arrows_add_gridpoints(arrows, geo, geo%gridpoints%fx, geo%gridpoints%fy)
      call draw_vectors(scene, arrows, opts, dark_green, 'gridpoint forces, unbalanced (N)')
   end subroutine layer_gpforces

   !> DSH: at each contact with a shear displacement, a half-arrow along the
   !> joint (fixed length) pointing the way side 1 moved relative to side 2.
   subroutine layer_shear_directions(scene, geo)
      type(plot_scene_t), intent(inout) :: scene
      type(geometry_t), intent(in) :: geo
      integer(ip) :: c
      integer :: n
      real(wp) :: tx, ty, h, px1, py1, px2, py2, us, umax
      real(wp), parameter :: arrow_len = 16.0_wp   ! page units
      call scene%add_legend(legend_title, 'directions of shear displacement', colour=red)
      umax = 0.0_wp
      do c = 1, geo%contacts%n
         if (geo%contacts%live(c)) umax = max(umax, abs(geo%contacts%state%us(c)))
      end do
      n = 0
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         us = geo%contacts%state%us(c)
         ! below a millionth of the largest: no direction worth showing
         if (us == 0.0_wp .or. abs(us) <= 1.0e-6_wp*umax) cycle
         tx = -geo%contacts%ny(c)
         ty = geo%contacts%nx(c)
         if (us < 0.0_wp) then
            tx = -tx
            ty = -ty
         end if
         call scene%to_page(geo%contacts%x(c), geo%contacts%y(c), px1, py1)
         if (px1 < scene%vx0 .or. px1 > scene%vx1 .or. py1 < scene%vy0 .or. py1 > scene%vy1) cycle
         h = 0.5_wp*arrow_len
         px2 = px1 + h*tx
         py2 = py1 + h*ty
         call scene%arrow(px1 - h*tx, py1 - h*ty, px2, py2, red, 1.2_wp, .true., head_max=6.0_wp)
         n = n + 1
      end do
      call scene%add_legend(legend_text, itoa(n)//' contact(s) with shear displacement')
      call scene%add_legend(legend_text, 'arrow: sense of us (tangent (-ny, nx) when us > 0)')
   end subroutine layer_shear_directions

end module plot_profiles
