!> Fluid-flow layers of PLOT (manual Section 4.6 keyword table): APERTURE,
!> FLOW, PP (line thickness along the joints) and VFLOW, FVEL (vectors along
!> the joints at the contact points). They draw the state of the last fluid
!> step (model%fluid: apertures, flow rates, domain pressures); a model
!> without a fluid part says so in the legend. See docs/plot.md.
module plot_fluid
   use core_kinds, only: wp, ip
   use model_state, only: model_t
   use model_geometry, only: geometry_t
   use model_fluid, only: fluid_t
   use plot_scene, only: plot_scene_t, legend_text, legend_line, legend_title, red, blue, &
                         format_number
   use plot_layers, only: layer_options_t, draw_vectors, arrow_set_t, arrows_reserve, &
                          arrows_push, plot_contact_segment => contact_segment, &
                          plot_thick_max => thick_max
   implicit none
   private
   public :: plot_fluid_layer, plot_fluid_names, plot_contact_pressures

   !> Layers this module draws (canonical PLOT keyword names).
   character(len=16), parameter :: plot_fluid_names(5) = [character(len=16) :: &
      'APERTURE', 'FLOW', 'PP', 'VFLOW', 'FVEL']

contains

   !> Draw fluid layer `name` (one of `plot_fluid_names`) of `model`.
   subroutine plot_fluid_layer(scene, model, name, opts)
      type(plot_scene_t), intent(inout) :: scene
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: name
      type(layer_options_t), intent(in) :: opts
      real(wp), allocatable :: val(:)
      integer(ip) :: nc
      if (.not. allocated(model%fluid)) then
         call scene%add_legend(legend_title, title_of(name))
         call scene%add_legend(legend_text, '(no fluid: give FLUID first)')
         return
      end if
      associate (fl => model%fluid, geo => model%geometry)
         ! the fluid arrays cover the contacts of the last fluid step
         nc = min(geo%contacts%n, fl%nc)
         allocate (val(max(1_ip, nc)))
         val = 0.0_wp
         select case (name)
         case ('APERTURE')
            val(1:nc) = fl%aperture(1:nc)
            call thickness(val(1:nc), .false.)
         case ('FLOW')
            val(1:nc) = abs(fl%q(1:nc))
            call thickness(val(1:nc), .false.)
         case ('PP')
            call plot_contact_pressures(fl, geo, nc, val)
            call thickness(val(1:nc), .true.)
         case ('VFLOW')
            call vectors(fl, geo, nc, .false.)
         case ('FVEL')
            call vectors(fl, geo, nc, .true.)
         end select
      end associate
   contains
      !> val(c) as line thickness along each contact: plot_thick_max x
      !> |val| / reference (<sc>, else the largest |val|); negative values
      !> (PP under SET EFF) blue, positive red.
      subroutine thickness(v, signed)
         real(wp), intent(in) :: v(:)
         logical, intent(in) :: signed
         real(wp) :: vmax, ref, w
         integer(ip) :: c
         call scene%add_legend(legend_title, title_of(name), colour=blue)
         vmax = 0.0_wp
         do c = 1, size(v, kind=ip)
            if (model%geometry%contacts%live(c)) vmax = max(vmax, abs(v(c)))
         end do
         call scene%add_legend(legend_text, 'maximum = '//format_number(vmax))
         ref = vmax
         if (opts%has_scale) ref = opts%scale
         if (ref <= 0.0_wp) then
            call scene%add_legend(legend_text, '(all values are zero)')
            return
         end if
         do c = 1, size(v, kind=ip)
            if (.not. model%geometry%contacts%live(c) .or. v(c) == 0.0_wp) cycle
            w = max(0.5_wp, min(3.0_wp*plot_thick_max, plot_thick_max*abs(v(c))/ref))
            if (signed .and. v(c) < 0.0_wp) then
               call plot_contact_segment(scene, model%geometry, c, red, w)
            else
               call plot_contact_segment(scene, model%geometry, c, blue, w)
            end if
         end do
         call scene%add_legend(legend_line, '= '//format_number(ref), colour=blue, &
                               width=plot_thick_max)
         if (signed) call scene%add_legend(legend_line, '= -'//format_number(ref), colour=red, &
                                           width=plot_thick_max)
      end subroutine thickness

      !> Flow (VFLOW: q) or fluid velocity (FVEL: q / a) along each joint at
      !> its contact point, pointing the way the fluid flows.
      subroutine vectors(fl, geo, n, velocity)
         type(fluid_t), intent(in) :: fl
         type(geometry_t), intent(in) :: geo
         integer(ip), intent(in) :: n
         logical, intent(in) :: velocity
         type(arrow_set_t) :: arrows
         real(wp) :: tx, ty, dx, dy, mag
         integer(ip) :: c
         call arrows_reserve(arrows, n)
         do c = 1, n
            if (.not. geo%contacts%live(c) .or. fl%q(c) == 0.0_wp) cycle
            mag = fl%q(c)
            if (velocity) then
               if (fl%aperture(c) <= 0.0_wp) cycle
               mag = mag/fl%aperture(c)
            end if
            ! from the side-1 domain towards the side-2 domain, along the joint
            call domain_point(fl, geo, c, geo%contacts%dom1(c), dx, dy)
            call domain_point(fl, geo, c, geo%contacts%dom2(c), tx, ty)
            dx = tx - dx
            dy = ty - dy
            tx = -geo%contacts%ny(c)
            ty = geo%contacts%nx(c)
            if (dx*tx + dy*ty < 0.0_wp) then
               tx = -tx
               ty = -ty
            end if
            call arrows_push(arrows, geo%contacts%x(c), geo%contacts%y(c), mag*tx, mag*ty)
         end do
         call draw_vectors(scene, arrows, opts, blue, title_of(name))
      end subroutine vectors
   end subroutine plot_fluid_layer

   !> Where domain d of contact c lies: its position, or the contact point
   !> for the outer domain.
   subroutine domain_point(fl, geo, c, d, x, y)
      type(fluid_t), intent(in) :: fl
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: c, d
      real(wp), intent(out) :: x, y
      x = geo%contacts%x(c)
      y = geo%contacts%y(c)
      if (d < 1 .or. d > min(geo%domains%n, fl%nd)) return
      if (geo%domains%outer(d)) return
      x = fl%xd(d)
      y = fl%yd(d)
   end subroutine domain_point

   !> Fluid pressure at each contact: the mean of its inner domains'
   !> pressures (under SET -EFF a dry domain counts 0).
   subroutine plot_contact_pressures(fl, geo, n, val)
      type(fluid_t), intent(in) :: fl
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: n
      real(wp), intent(inout) :: val(:)
      integer(ip) :: c, d
      integer :: s, m
      real(wp) :: p
      do c = 1, n
         val(c) = 0.0_wp
         if (.not. geo%contacts%live(c)) cycle
         m = 0
         do s = 1, 2
            d = merge(geo%contacts%dom1(c), geo%contacts%dom2(c), s == 1)
            if (d < 1 .or. d > min(geo%domains%n, fl%nd)) cycle
            if (geo%domains%outer(d)) cycle
            p = fl%p(d)
            if (.not. fl%eff) p = max(p, 0.0_wp)
            val(c) = val(c) + p
            m = m + 1
         end do
         if (m > 0) val(c) = val(c)/real(m, wp)
      end do
   end subroutine plot_contact_pressures

   pure function title_of(name) result(title)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: title
      select case (name)
      case ('APERTURE')
         title = 'joint hydraulic aperture (m)'
      case ('FLOW')
         title = 'joint flow rate (m2/s)'
      case ('PP')
         title = 'joint fluid pressure (Pa)'
      case ('VFLOW')
         title = 'flow vectors'
      case default
         title = 'fluid velocity in joints (m/s)'
      end select
   end function title_of

end module plot_fluid
