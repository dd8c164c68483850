!> PLOT keyword <switch..> <keyword ..>: one picture from several layers.
!> `plot_build` turns a request (layer names with their options, the
!> history supplements, the window) into a scene with its legend; the
!> command layer only translates the parsed command into the request.
module plot_build
   use core_kinds, only: wp
   use core_error, only: error_t, set_error
   use core_interrupt, only: interrupt_pending
   use model_state, only: model_t
   use plot_scene, only: plot_scene_t, item_polygon, grey
   use plot_layers, only: layer_options_t, plot_model_layer, plot_layer_names
   use plot_zones, only: plot_zone_layer, plot_zone_area_layer, contour_names, &
                         plot_zone_layer_names
   use plot_fluid, only: plot_fluid_layer, plot_fluid_names
   use plot_profiles, only: plot_profile_layer, plot_profile_names
   use plot_history, only: history_request_t, plot_history_graph
   use plot_legend, only: plot_compose_legend
   implicit none
   private
   public :: plot_request_t, plot_request_add, plot_build_scene, plot_auto_window

   !> One PLOT command, ready to draw.
   type :: plot_request_t
      integer :: n = 0
      character(len=16), allocatable :: names(:)      !< model layers in command order
      type(layer_options_t), allocatable :: opts(:)
      logical :: nc = .false.                         !< NC anywhere: no corner rounding
      logical :: noheading = .false.
      logical :: history = .false.
      type(history_request_t) :: hist
      logical :: window_auto = .true.
      real(wp) :: window(4) = 0.0_wp                  !< xl xu yl yu (WINDOW command)
   end type plot_request_t

contains

   !> Append a model layer (with <sc> when `has_scale`).
   subroutine plot_request_add(req, name, scale, has_scale)
      type(plot_request_t), intent(inout) :: req
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: scale
      logical, intent(in) :: has_scale
      character(len=16), allocatable :: tn(:)
      type(layer_options_t), allocatable :: to(:)
      if (.not. allocated(req%names)) allocate (req%names(8), req%opts(8))
      if (req%n >= size(req%names)) then
         allocate (tn(2*req%n), to(2*req%n))
         tn(1:req%n) = req%names(1:req%n)
         to(1:req%n) = req%opts(1:req%n)
         call move_alloc(tn, req%names)
         call move_alloc(to, req%opts)
      end if
      req%n = req%n + 1
      req%names(req%n) = name
      req%opts(req%n)%scale = scale
      req%opts(req%n)%has_scale = has_scale
   end subroutine plot_request_add

   !> Default window (manual 4.6 WINDOW): a square slightly larger (5% each
   !> side) than the extent of the live blocks; the unit square when there
   !> are none.
   function plot_auto_window(model) result(w)
      type(model_t), intent(in) :: model
      real(wp) :: w(4)
      real(wp) :: xmin, xmax, ymin, ymax, side, cx, cy
      integer :: b
      logical :: any_block
      any_block = .false.
      xmin = huge(1.0_wp); xmax = -huge(1.0_wp); ymin = huge(1.0_wp); ymax = -huge(1.0_wp)
      associate (bl => model%geometry%blocks)
         do b = 1, bl%n
            if (.not. bl%live(b)) cycle
            any_block = .true.
            xmin = min(xmin, bl%xmin(b)); xmax = max(xmax, bl%xmax(b))
            ymin = min(ymin, bl%ymin(b)); ymax = max(ymax, bl%ymax(b))
         end do
      end associate
      if (.not. any_block) then
         w = [0.0_wp, 1.0_wp, 0.0_wp, 1.0_wp]
         return
      end if
      ! blocks move: take the corners, which the engine keeps current
      associate (c => model%geometry%corners)
         do b = 1, c%n
            if (.not. c%live(b)) cycle
            xmin = min(xmin, c%x(b)); xmax = max(xmax, c%x(b))
            ymin = min(ymin, c%y(b)); ymax = max(ymax, c%y(b))
         end do
      end associate
      side = 1.1_wp*max(xmax - xmin, ymax - ymin)
      if (side <= 0.0_wp) side = 1.0_wp
      cx = 0.5_wp*(xmin + xmax)
      cy = 0.5_wp*(ymin + ymax)
      w = [cx - 0.5_wp*side, cx + 0.5_wp*side, cy - 0.5_wp*side, cy + 0.5_wp*side]
   end function plot_auto_window

   !> Build the picture of `req`. `unknown` returns layers no module draws
   !> yet (the caller reports them); the scene holds the others.
   subroutine plot_build_scene(model, req, scene, unknown, error)
      type(model_t), intent(in) :: model
      type(plot_request_t), intent(in) :: req
      type(plot_scene_t), intent(out) :: scene
      character(len=:), allocatable, intent(out) :: unknown
      type(error_t), allocatable, intent(out) :: error
      type(layer_options_t) :: opts
      real(wp) :: window(4)
      integer :: k, pass
      logical :: handled, filled, tension_line, area
      character(len=:), allocatable :: name
      unknown = ''
      if (req%history .and. req%n > 0) then
         call set_error(error, 'PLOT HISTORY: a history plot cannot be combined with ' // &
                        'model layers such as '//trim(req%names(1))//' (use two PLOT commands)')
         return
      end if
      call scene%init(.not. req%noheading)
      scene%heading = model%heading
      scene%time = model%mech%time
      if (allocated(model%thermal)) scene%thermal_time = model%thermal%time
      scene%cycle = model%mech%step
      if (req%history) then
         scene%what = 'HISTORY'
         call plot_history_graph(scene, model%hist, req%hist, error)
         if (allocated(error)) return
      else
         window = req%window
         if (req%window_auto) window = plot_auto_window(model)
         call scene%set_view(window, [scene%vx0, scene%vx1, scene%vy0, scene%vy1], .true.)
         call scene%polyline(item_polygon, [scene%vx0, scene%vx1, scene%vx1, scene%vx0], &
                             [scene%vy0, scene%vy0, scene%vy1, scene%vy1], grey, 0.8_wp)
         ! area fills first (MAT, contours, TENSION), so that lines and vectors
         ! stay on top
         filled = .false.
         ! TENSION with a filled contour: its pink zones would hide the bands
         ! or be hidden by them, so only its SMAX = 0 line is drawn, on top
         tension_line = .false.
         do k = 1, req%n
            if (any(contour_names == req%names(k)) .and. .not. req%opts(k)%line) &
               tension_line = .true.
         end do
         do pass = 1, 2
            do k = 1, req%n
               ! Ctrl-C / SIGTERM: stop between layers, no picture is kept
               if (interrupt_pending()) then
                  call set_error(error, 'PLOT interrupted: no picture was drawn')
                  return
               end if
               area = req%names(k) == 'MAT' .or. req%names(k) == 'ROTATE' .or. &
                      plot_zone_area_layer(trim(req%names(k)))
               if (tension_line .and. req%names(k) == 'TENSION') area = .false.
               if ((pass == 1) .neqv. area) cycle
               opts = req%opts(k)
               opts%nc = req%nc
               if (tension_line .and. req%names(k) == 'TENSION') opts%as_lines = .true.
               ! one filled contour per picture: bands of a second field would
               ! cover the first, so later contour keywords are drawn as lines
               if (any(contour_names == req%names(k)) .and. .not. opts%line) then
                  if (filled) then
                     opts%line = .true.
                     opts%as_lines = .true.
                  end if
                  filled = .true.
               end if
               ! each layer module draws the names it lists, in this order
               name = trim(req%names(k))
               handled = .true.
               if (any(plot_layer_names == name)) then
                  call plot_model_layer(scene, model, name, opts)
               else if (any(plot_zone_layer_names == name)) then
                  call plot_zone_layer(scene, model, name, opts)
               else if (any(plot_fluid_names == name)) then
                  call plot_fluid_layer(scene, model, name, opts)
               else if (any(plot_profile_names == name)) then
                  call plot_profile_layer(scene, model, name, opts, error)
                  if (allocated(error)) return
               else
                  handled = .false.
               end if
               if (handled) then
                  scene%what = trim(scene%what)//' '//trim(req%names(k))
               else
                  unknown = trim(unknown)//' '//trim(req%names(k))
               end if
            end do
         end do
         scene%what = trim(adjustl(scene%what))
         unknown = trim(adjustl(unknown))
      end if
      call plot_compose_legend(scene)
   end subroutine plot_build_scene

end module plot_build
