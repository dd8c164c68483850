!> Plotting commands (manual Section 4.6): PLOT builds a picture, COPY
!> writes the last picture to a file, WINDOW sets the plotting window, and
!> the SET keywords PLOT (device) and OUTPUT (default file) choose the
!> default route.
!>
!> There is no screen: interactively a PLOT keeps its picture until COPY
!> writes it. In batch mode (where the 1989 program sent every plot to the
!> default file PLT), a picture that was not copied is written to the
!> default route when the next PLOT replaces it and when the run ends. The
!> default route is the SET OUTPUT file (PLT if none) in the SET PLOT
!> format (PNG unless set); a COPY file named .ps/.eps or .png is written
!> in that format whatever the route.
!>
!> Plot settings belong to the session, not the model: the manual keeps
!> the route out of save files on purpose (SET, Section 4.6).
module commands_plot
   use core_kinds, only: wp
   use core_error, only: error_t, set_error
   use core_files, only: check_output_file

   use core_output, only: output_t
   use model_state, only: model_t
   use contact_refresh, only: geometry_refresh
   use commands_parser, only: parsed_t, value_text
   use commands_context, only: context_t, registry_t
   use commands_plot_state, only: plot_state_t
   use plot_scene, only: plot_scene_t, format_number
   use plot_build, only: plot_request_t, plot_request_add, plot_build_scene, plot_auto_window
   use plot_device, only: plot_device_t
   use plot_layers, only: layer_options_t
   use plot_zones, only: contour_names
   use plot_profiles, only: profile_quantity_name
   use commands_tokens, only: to_upper
   use plot_factory, only: plot_device_create, plot_device_for_file
   use plot_thist, only: plot_thist_scene
   implicit none
   private
   public :: register_plot_commands
   public :: plot_state_t, handle_plot, handle_copy, handle_window, set_plot_keyword
   public :: plot_session_end, plot_default_file

   !> Default plot file of the manual (batch mode, no SET OUTPUT).
   character(len=*), parameter :: plot_default_file = 'PLT'


contains

   !> The commands of this family in the registry (commands_context).
   subroutine register_plot_commands(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('plot', 'PLot', '', '', 'APerture [r];Axial [r];BLocks;BNum;BOundary;' // &
                   'Cable;CForce [r];CLosure [r];Contacts;Displacements [r];DOmains;DSh;' // &
                   'Flow [r];FRactures;FVel [r];Gpforces [r];History qq*;Hoek;JLine rrrra;' // &
                   'Joint rrrra[p];MAT;MOhr;Plasticity;PP [r];REinforce;Rotate a;SDif;' // &
                   'SHear [r];SLip;SMIN;SMAX;Stresses [r];STRUct;SXX;SYY;SYX;SXY;Tension;' // &
                   'Velocity [r];Vflow [r];Window;XDisplacement;XVel;YDisplacement;YVel;ZOnes;' // &
                   'GRid [qq];Interval p;Line [rrrr];Max rr;NC;NOheading;ZERo;AB q;ABC q;' // &
                   'XRev;XWindow rr;YRev;YWindow rr;TEmperature;THist qq*', '4.6', &
                   'draw the model, its fields or histories (PostScript or PNG)', run_plot)
      call reg%add('plot', 'COPY', '[s]', '', '', '4.6', 'write the last picture to a file', &
                   run_copy)
      call reg%add('plot', 'Window', '[rrrr]', '', 'AUTO', '4.6', &
                   'the plotting window: xl xu yl yu, or AUTO', run_window, unit='m')
      call reg%add_set('plot', 'CGA;CHAR i;EGA;Mono;Output s;PLOT;HP;SPerry;PS;PNG;XYwrite', &
                       set_plot)
   end subroutine register_plot_commands

   !> PLOT keyword <switch..> <keyword ..>
   subroutine handle_plot(state, model, parsed, batch, out, error)
      type(plot_state_t), intent(inout) :: state
      type(model_t), intent(inout) :: model
      type(parsed_t), intent(in) :: parsed
      logical, intent(in) :: batch
      type(output_t), intent(in) :: out
      type(error_t), allocatable, intent(out) :: error
      type(plot_request_t) :: req
      type(plot_scene_t) :: scene
      character(len=:), allocatable :: unknown, word, quantity
      integer :: k, j
      logical :: skipped, scaled
      skipped = .false.
      ! PLOT THIST n1 <n2 ..> (Section 7.4.2): its own picture (plot_thist)
      k = parsed%find('THIST')
      if (k > 0) then
         call plot_thist_only(state, model, parsed, k, batch, out, error)
         return
      end if
      do k = 1, parsed%nitems
         associate (name => parsed%items(k)%name, count => parsed%items(k)%count)
            select case (name)
            case ('')
            case ('NC')
               req%nc = .true.
            case ('NOHEADING')
               req%noheading = .true.
            case ('HISTORY')
               req%history = .true.
               req%hist%n = count
               allocate (req%hist%ids(count))
               do j = 1, count
                  req%hist%ids(j) = parsed%int_at(k, j)
               end do
            case ('AB', 'ABC')
               req%hist%abscissa = parsed%int_at(k, 1)
            case ('XREV')
               req%hist%xrev = .true.
            case ('YREV')
               req%hist%yrev = .true.
            case ('XWINDOW')
               req%hist%has_xwin = .true.
               req%hist%xwin = [parsed%real_at(k, 1), parsed%real_at(k, 2)]
            case ('YWINDOW')
               req%hist%has_ywin = .true.
               req%hist%ywin = [parsed%real_at(k, 1), parsed%real_at(k, 2)]
            case ('GRID', 'INTERVAL', 'LINE', 'MAX', 'ZERO')
               ! a switch sets the keyword before it (manual 4.6)
               if (req%n == 0) then
                  call set_error(error, 'PLOT '//name//': a switch follows the keyword it ' // &
                                 'modifies (e.g. PLOT SXX '//name//' ...)')
                  return
               end if
               call set_switch(req%opts(req%n), parsed, k, error)
               if (allocated(error)) return
               if (.not. any(contour_names == req%names(req%n))) then
                  ! ROTATE's bands take INTERVAL and MAX too
                  if (.not. (name == 'GRID' .and. req%names(req%n) == 'TENSION') .and. &
                      .not. (req%names(req%n) == 'ROTATE' .and. &
                             (name == 'INTERVAL' .or. name == 'MAX'))) skipped = .true.
               end if
            case ('JLINE', 'JOINT')
               ! x1 y1 x2 y2 q <tolc>: the coordinates are not a scale (x1 = 0
               ! was once read as "a scale > 0, got 0")
               call plot_request_add(req, name, 0.0_wp, .false.)
               do j = 1, 4
                  req%opts(req%n)%profile_xy(j) = parsed%real_at(k, j)
               end do
               word = to_upper(parsed%text_at(k, 5))
               quantity = profile_quantity_name(word)
               if (len(quantity) == 0) then
                  call set_error(error, 'PLOT '//name//": expected APE, FLOW, NSTR, PP, SSTR, " // &
                                 "VEL, NDIS, SDIS or a contact offset koff after x1 y1 x2 y2, got '" &
                                 //parsed%text_at(k, 5)//"'")
                  return
               end if
               req%opts(req%n)%quantity = quantity
               if (quantity == 'KOFF') read (word, *) req%opts(req%n)%koff
               if (all(req%opts(req%n)%profile_xy(1:2) == req%opts(req%n)%profile_xy(3:4))) then
                  call set_error(error, 'PLOT '//name//': expected two different points x1 y1 ' // &
                                 'x2 y2, got the same point twice')
                  return
               end if
               if (count >= 6) then
                  req%opts(req%n)%has_tolc = .true.
                  req%opts(req%n)%tolc = parsed%real_at(k, 6)
               end if
            case ('ROTATE')
               call plot_request_add(req, name, 0.0_wp, .false.)
               word = to_upper(parsed%text_at(k, 1))
               if (len(word) >= 1 .and. word == 'BLOCK'(1:min(5, len(word)))) then
                  req%opts(req%n)%quantity = 'BLOCK'
               else if (len(word) >= 1 .and. word == 'ZONE'(1:min(4, len(word)))) then
                  req%opts(req%n)%quantity = 'ZONE'
               else
                  call set_error(error, "PLOT ROTATE: expected BLOCK or ZONE, got '"// &
                                 parsed%text_at(k, 1)//"'")
                  return
               end if
            case default
               ! (nested: Fortran's .and. may evaluate both sides, and with
               ! no value the item's first index is one past the last value)
               scaled = .false.
               if (count >= 1) scaled = parsed%values(parsed%items(k)%first)%kind /= value_text
               if (scaled) then
                  call plot_request_add(req, name, parsed%real_at(k, 1), .true.)
               else
                  call plot_request_add(req, name, 0.0_wp, .false.)
               end if
            end select
         end associate
      end do
      if (req%n == 0 .and. .not. req%history) then
         call set_error(error, 'PLOT: expected at least one thing to plot (e.g. BLOCKS)')
         return
      end if
      if (.not. req%history .and. .not. model%geometry%block_created) then
         call set_error(error, 'PLOT: no BLOCK has been created')
         return
      end if
      if (req%history .and. model%hist%n == 0) then
         ! nothing to draw, but not worth ending a batch run for: the picture
         ! is the empty axes, so that the COPY after it still works
         call out%line('*** Warning: PLOT HISTORY: no histories are defined (HISTORY ' // &
                       'command); the plot is empty')
         req%hist%n = 0
         deallocate (req%hist%ids)
         allocate (req%hist%ids(0))
         req%hist%abscissa = 0
      end if
      do k = 1, req%n
         if (req%opts(k)%has_scale .and. req%opts(k)%scale <= 0.0_wp) then
            call set_error(error, 'PLOT '//trim(req%names(k))// &
                           ': expected a scale > 0, got '//format_number(req%opts(k)%scale))
            return
         end if
      end do
      req%window_auto = state%window_auto
      req%window = state%window
      if (.not. req%history) call geometry_refresh(model%geometry)
      call plot_build_scene(model, req, scene, unknown, error)
      if (allocated(error)) return
      if (len(unknown) > 0) call out%line('*** PLOT '//unknown//': not yet implemented')
      if (skipped) call out%line('*** PLOT: contour switches (GRID, INTERVAL, LINE, MAX, ' // &
                                 'ZERO) after a keyword that is not a contour are ignored')
      call keep_scene(state, scene, batch, out, error)
   end subroutine handle_plot

   !> PLOT THIST n1 <n2 ..>, alone on the line (NOHEADING allowed).
   subroutine plot_thist_only(state, model, parsed, k, batch, out, error)
      type(plot_state_t), intent(inout) :: state
      type(model_t), intent(inout) :: model
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k
      logical, intent(in) :: batch
      type(output_t), intent(in) :: out
      type(error_t), allocatable, intent(out) :: error
      type(plot_scene_t) :: scene
      integer, allocatable :: ids(:)
      integer :: j
      do j = 1, parsed%nitems
         if (j == k .or. parsed%items(j)%name == 'NOHEADING' .or. parsed%items(j)%name == '') &
            cycle
         call set_error(error, 'PLOT THIST: a thermal history plot cannot be combined with ' &
                        //parsed%items(j)%name//' (use two PLOT commands)')
         return
      end do
      allocate (ids(parsed%items(k)%count))
      do j = 1, size(ids)
         ids(j) = int(parsed%int_at(k, j))
      end do
      call plot_thist_scene(model, ids, parsed%find('NOHEADING') == 0, scene, error)
      if (allocated(error)) return
      call keep_scene(state, scene, batch, out, error)
   end subroutine plot_thist_only

   !> The new picture `scene` becomes the current one of `state`; in batch the
   !> picture it replaces, unless copied, goes to the default route first.
   subroutine keep_scene(state, scene, batch, out, error)
      type(plot_state_t), intent(inout) :: state
      type(plot_scene_t), intent(inout) :: scene
      logical, intent(in) :: batch
      type(output_t), intent(in) :: out
      type(error_t), allocatable, intent(out) :: error
      if (batch .and. state%has_scene .and. .not. state%copied) then
         call write_scene(state, state%scene, '', out, error)
         if (allocated(error)) return
      end if
      call move_scene(scene, state%scene)
      state%has_scene = .true.
      state%copied = .false.
      if (.not. batch) call out%line('Plot ready ('//plot_what(state%scene)// &
                                     '); there is no screen: COPY [file] writes it')
   end subroutine keep_scene

   !> A contour switch (item k) into the options of the keyword before it.
   subroutine set_switch(opts, parsed, k, error)
      type(layer_options_t), intent(inout) :: opts
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k
      type(error_t), allocatable, intent(out) :: error
      integer :: j
      select case (parsed%items(k)%name)
      case ('GRID')
         opts%grid = .true.
      case ('INTERVAL')
         opts%has_interval = .true.
         opts%interval = parsed%real_at(k, 1)
      case ('ZERO')
         opts%zero = .true.
      case ('LINE')
         opts%line = .true.
         do j = 1, min(4, parsed%items(k)%count)
            opts%line_xy(j) = parsed%real_at(k, j)
         end do
      case ('MAX')
         opts%has_max = .true.
         opts%vmax = parsed%real_at(k, 1)
         opts%vmin = parsed%real_at(k, 2)
         if (opts%vmax <= opts%vmin) then
            call set_error(error, 'PLOT MAX: expected vmax > vmin, got '// &
                           format_number(opts%vmax)//' '//format_number(opts%vmin))
         end if
      end select
   end subroutine set_switch

   !> COPY <file>: write the last picture.
   subroutine handle_copy(state, parsed, out, error)
      type(plot_state_t), intent(inout) :: state
      type(parsed_t), intent(in) :: parsed
      type(output_t), intent(in) :: out
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: file
      if (.not. state%has_scene) then
         call set_error(error, 'COPY: there is no plot to copy (give a PLOT command first)')
         return
      end if
      file = ''
      if (parsed%nitems >= 1) then
         if (parsed%items(1)%count >= 1) file = parsed%text_at(1, 1)
      end if
      call write_scene(state, state%scene, file, out, error)
      if (allocated(error)) return
      state%copied = .true.
   end subroutine handle_copy

   !> WINDOW xl xu yl yu | AUTO; no argument prints the window.
   subroutine handle_window(state, model, parsed, out, error)
      type(plot_state_t), intent(inout) :: state
      type(model_t), intent(in) :: model
      type(parsed_t), intent(in) :: parsed
      type(output_t), intent(in) :: out
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: w(4)
      integer :: j
      if (parsed%find('AUTO') > 0) then
         if (parsed%items(1)%count > 0) then
            call set_error(error, 'WINDOW: give either xl xu yl yu or AUTO, not both')
            return
         end if
         state%window_auto = .true.
      else if (parsed%items(1)%count == 4) then
         do j = 1, 4
            w(j) = parsed%real_at(1, j)
         end do
         if (w(2) <= w(1) .or. w(4) <= w(3)) then
            call set_error(error, 'WINDOW: expected xl < xu and yl < yu, got '// &
                           format_number(w(1))//' '//format_number(w(2))//' '// &
                           format_number(w(3))//' '//format_number(w(4)))
            return
         end if
         state%window = w
         state%window_auto = .false.
      end if
      if (state%window_auto) then
         w = plot_auto_window(model)
         call out%line('Window (automatic): x '//format_number(w(1))//' to '// &
                       format_number(w(2))//', y '//format_number(w(3))//' to '// &
                       format_number(w(4)))
      else
         w = state%window
         call out%line('Window: x '//format_number(w(1))//' to '//format_number(w(2))// &
                       ', y '//format_number(w(3))//' to '//format_number(w(4)))
      end if
   end subroutine handle_window

   !> SET keyword k of the plotting family: PLOT <PS|PNG|HP|SPERRY>, PS,
   !> PNG, HP, SPERRY, OUTPUT file, and the 1989 screen settings CGA, EGA,
   !> MONO, CHAR, XYWRITE (no screen here: noted and ignored).
   subroutine set_plot_keyword(state, parsed, k, out, error)
      type(plot_state_t), intent(inout) :: state
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k
      type(output_t), intent(in) :: out
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: file, upper_file
      class(plot_device_t), allocatable :: device
      select case (parsed%items(k)%name)
      case ('PLOT')
         if (k == parsed%nitems) then
            call set_error(error, 'SET PLOT: expected a device after PLOT (PS or PNG)')
            return
         end if
         select case (parsed%items(k + 1)%name)
         case ('PS', 'PNG', 'HP', 'SPERRY')
         case default
            call set_error(error, 'SET PLOT: expected a device after PLOT (PS or PNG)')
            return
         end select
      case ('PS', 'PNG')
         call plot_device_create(parsed%items(k)%name, device, error)
         if (allocated(error)) return
         state%route = device%name()
         call out%line('Plots are written as '//state%route//' by default.')
      case ('HP', 'SPERRY')
         call out%line('*** SET '//parsed%items(k)%name//': pen plotters and the Sperry ' // &
                       'printer are not supported; plots stay '//route(state))
      case ('OUTPUT')
         file = parsed%text_at(k, 1)
         upper_file = to_upper(file)
         select case (upper_file)
         case ('COM1', 'COM2', 'LPT1', 'CON')
            state%output = ''
            call out%line('*** SET OUTPUT '//file//': there is no such device here; plots ' // &
                          'go to the file '//plot_default_file)
         case default
            state%output = file
            call out%line('Plots are copied to the file '//file//' by default.')
         end select
      case ('CGA', 'EGA', 'MONO', 'CHAR', 'XYWRITE')
         call out%line('*** SET '//parsed%items(k)%name//': there is no screen device; ignored')
      end select
   end subroutine set_plot_keyword

   !> End of a batch run: the last picture, if never copied, goes to the
   !> default route.
   subroutine plot_session_end(state, batch, out)
      type(plot_state_t), intent(inout) :: state
      logical, intent(in) :: batch
      type(output_t), intent(in) :: out
      type(error_t), allocatable :: error
      if (.not. batch .or. .not. state%has_scene .or. state%copied) return
      call write_scene(state, state%scene, '', out, error)
      if (allocated(error)) call out%line('*** Error: '//error%message)
      state%copied = .true.
   end subroutine plot_session_end

   !> Write `scene` to `file`, or to the default route when `file` is ''.
   subroutine write_scene(state, scene, file, out, error)
      type(plot_state_t), intent(in) :: state
      type(plot_scene_t), intent(in) :: scene
      character(len=*), intent(in) :: file
      type(output_t), intent(in) :: out
      type(error_t), allocatable, intent(out) :: error
      class(plot_device_t), allocatable :: device
      character(len=:), allocatable :: path
      path = file
      if (len(path) == 0) then
         path = plot_default_file
         if (allocated(state%output)) then
            if (len(state%output) > 0) path = state%output
         end if
      end if
      ! a folder, device or FIFO is refused before anything is written
      call check_output_file('PLOT', path, error)
      if (allocated(error)) return
      call plot_device_create(plot_device_for_file(path, route(state)), device, error)
      if (allocated(error)) return
      call device%write(scene, path, error)
      if (allocated(error)) return
      call out%line('Plot ('//plot_what(scene)//') written to '//path//' ('// &
                    device%name()//')')
   end subroutine write_scene

   function route(state) result(name)
      type(plot_state_t), intent(in) :: state
      character(len=:), allocatable :: name
      name = 'PNG'
      if (allocated(state%route)) name = state%route
   end function route

   function plot_what(scene) result(text)
      type(plot_scene_t), intent(in) :: scene
      character(len=:), allocatable :: text
      text = scene%what
      if (len(text) == 0) text = 'empty'
   end function plot_what

   !> Hand a finished scene over without copying its arrays.
   subroutine move_scene(from, to)
      type(plot_scene_t), intent(inout) :: from
      type(plot_scene_t), intent(inout) :: to
      to%page_w = from%page_w
      to%page_h = from%page_h
      to%vx0 = from%vx0
      to%vx1 = from%vx1
      to%vy0 = from%vy0
      to%vy1 = from%vy1
      to%window = from%window
      to%sx = from%sx
      to%sy = from%sy
      to%ox = from%ox
      to%oy = from%oy
      to%heading_on = from%heading_on
      to%heading = from%heading
      to%time = from%time
      to%cycle = from%cycle
      to%what = from%what
      to%nitem = from%nitem
      to%npoint = from%npoint
      to%nlegend = from%nlegend
      call move_alloc(from%items, to%items)
      call move_alloc(from%x, to%x)
      call move_alloc(from%y, to%y)
      call move_alloc(from%legend, to%legend)
   end subroutine move_scene

   subroutine run_plot(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      call handle_plot(ctx%plot, ctx%model, parsed, ctx%batch, ctx%out, error)
   end subroutine run_plot

   subroutine run_copy(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      call handle_copy(ctx%plot, parsed, ctx%out, error)
   end subroutine run_copy

   subroutine run_window(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      call handle_window(ctx%plot, ctx%model, parsed, ctx%out, error)
   end subroutine run_window


   !> SET PLOT, PS, PNG, HP, SPERRY, OUTPUT, CGA, EGA, MONO, CHAR, XYWRITE.
   subroutine set_plot(ctx, parsed, k, apply, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k
      logical, intent(in) :: apply
      type(error_t), allocatable, intent(out) :: error
      if (.not. apply) return
      call set_plot_keyword(ctx%plot, parsed, k, ctx%out, error)
   end subroutine set_plot

end module commands_plot
