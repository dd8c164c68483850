!> The commands of the session itself (manual Section 4.5): STOP, QUIT, END,
!> HEADING, CALL, RETURN, START, NEW and SET. SET's keywords act in order,
!> each in the module of its physics. HELP (not in the manual) prints the
!> command reference from the registry.
module commands_control
   use core_error, only: error_t, set_error
   use model_state, only: model_reset
   use commands_parser, only: parsed_t
   use commands_context, only: context_t, registry_t, context_push_file, context_pop_source, &
                               cannot_fail
   use commands_source, only: source_read_raw
   use engine_stages, only: cycle_report_t
   use commands_tokens, only: printable
   use commands_grammar, only: match_none, match_ambiguous
   use commands_help, only: help_list, help_command
   use commands_properties, only: handle_gravity
   use commands_geometry, only: set_geometry_keyword
   use commands_mechanics, only: set_mechanics_keyword
   use commands_plot, only: set_plot_keyword
   use commands_io, only: set_xform
   use commands_boundary, only: boundary_set_fup
   use commands_zpress, only: zpress_check, zpress_set
   use commands_thermal, only: is_thermal_set_keyword, set_thermal_keyword
   use commands_fluid, only: set_fluid_keyword, is_fluid_set_keyword
   implicit none
   private
   public :: register_control_commands

contains

   !> The commands of this family in the registry (commands_context).
   subroutine register_control_commands(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('control', 'STOp', '', '', '', '4.5', 'end the run', run_stop, in_check=.true.)
      call reg%add('control', 'Quit', '', '', '', '4.5', 'end the run (as STOP)', run_stop, &
                   in_check=.true.)
      call reg%add('control', 'End', '', '', '', '4.5', 'end the run (as STOP)', run_stop, &
                   in_check=.true.)
      call reg%add('control', 'HEading', '', '', '', '4.5', &
                   'the next input line is the title of the problem', run_heading, &
                   in_check=.true.)
      call reg%add('control', 'CALL', 's', '', '', '4.5', &
                   'read commands from a file (RETURN comes back)', run_call)
      call reg%add('control', 'RETurn', '', '', '', '4.5', &
                   'leave a CALLed file, back to the caller', run_return)
      call reg%add('control', 'Start', '', '', '', '4.5', 'start a new problem (as NEW)', run_new)
      call reg%add('control', 'NEW', '', '', '', '4.5', 'start a new problem: the model is empty', &
                   run_new)
      call reg%add('control', 'SEt', '', '', 'CSCAn q;CAPratio p;CLEmin p;DScan q;Edge p;EFF;' // &
                   '-EFF;FUP;-FUP;Gravity rr;JCondf c;JMatdf q;Log;ON;OFF;OVtol p;Ptol p;SFlow;' // &
                   '-SFlow;UPcon q;Write;-Write;Xform;YWtable r;ZPress rrrr;CGA;CHAR i;EGA;' // &
                   'Mono;Output s;PLOT;HP;SPerry;PS;PNG;XYwrite;NMECH q;NTHER c;THDT p;SEed i', &
                   '4.5', 'program settings: contact scans, tolerances, log, plot route, ..', &
                   run_set)
      call reg%note('UPCON', default='1')
      call reg%note('DSCAN', default='3')
      call reg%note('CSCAN', default='100')
      call reg%note('OVTOL', unit='m', default='half the rounding length')
      call reg%note('CLEMIN', unit='m', default='1/10 of the mean contact length')
      call reg%note('GRAVITY', unit='m/s^2', default='0 0')
      call reg%note('EDGE', unit='m', default='1')
      call reg%note('YWTABLE', unit='m')
      call reg%note('THDT', unit='s')
      call reg%add('control', 'HELp', '[a]', '', '', 'udec', &
                   'list the commands, or show one: syntax, keywords, units, defaults', run_help)
   end subroutine register_control_commands

   !> HELP: every command; HELP <command>: its page (commands_help), both from
   !> the registry the parser reads.
   subroutine run_help(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: name, closest
      integer :: k
      if (parsed%items(1)%count == 0) then
         call help_list(ctx%registry, ctx%grammar, ctx%out)
         return
      end if
      name = parsed%text_at(1, 1)
      k = ctx%grammar%find_command(name)
      if (k == match_ambiguous) then
         call set_error(error, "HELP: ambiguous command abbreviation '"//printable(name)// &
                        "' (could be "//ctx%grammar%command_candidates(name)//")")
         return
      else if (k == match_none) then
         closest = ctx%grammar%closest(name)
         if (len(closest) > 0) closest = ' (closest known commands: '//closest//')'
         call set_error(error, "HELP: unknown command '"//printable(name)//"'"//closest)
         return
      end if
      call help_command(ctx%registry, ctx%grammar, k, ctx%out)
   end subroutine run_help

   subroutine run_stop(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      call cannot_fail(error, parsed)
      ctx%stopped = .true.
   end subroutine run_stop

   subroutine run_heading(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      call cannot_fail(error, parsed)
      call do_heading(ctx, error)
   end subroutine run_heading

   subroutine run_call(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      call context_push_file(ctx, parsed%text_at(1, 1), error)
   end subroutine run_call

   subroutine run_return(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      call cannot_fail(error, parsed)
      if (ctx%depth <= 1 .or. ctx%sources(ctx%depth)%interactive) then
         call set_error(error, 'RETURN: not inside a CALLed file')
         return
      end if
      call context_pop_source(ctx)
   end subroutine run_return

   subroutine run_new(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      call cannot_fail(error, parsed)
      call model_reset(ctx%model)
      ctx%cycle = cycle_report_t()     ! PRINT CYCLE times this model's CYCLEs only
      call ctx%out%line('New problem: the model is empty.')
   end subroutine run_new

   subroutine run_set(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      call do_set(ctx, parsed, error)
   end subroutine run_set

   !> HEADING: the next input line is the title (prompt HEAD> interactively).
   subroutine do_heading(ctx, error)
      type(context_t), intent(inout) :: ctx
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text
      logical :: eof
      call source_read_raw(ctx%sources(ctx%depth), ctx%out, 'HEAD> ', text, eof)
      if (eof) then
         call set_error(error, 'HEADING: the title line is missing (end of input)')
         return
      end if
      if (ctx%check_only) return
      ctx%model%heading = printable_heading(text)
   end subroutine do_heading

   pure function printable_heading(text) result(clean)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: clean
      clean = trim(adjustl(text))
      if (len(clean) > 80) clean = clean(1:80)
   end function printable_heading

   !> SET: keywords act in order; those whose physics has not landed say so.
   subroutine do_set(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer :: k
      logical :: want_log, handled
      ! Validate first: LOG must be followed by ON or OFF.
      k = parsed%find('LOG')
      if (k > 0) then
         want_log = .false.
         if (k < parsed%nitems) then
            select case (parsed%items(k + 1)%name)
            case ('ON')
               want_log = .true.
            case ('OFF')
               want_log = .false.
            case default
               call set_error(error, 'SET LOG: expected ON or OFF after LOG')
               return
            end select
         else
            call set_error(error, 'SET LOG: expected ON or OFF after LOG')
            return
         end if
      end if
      if (parsed%find('FUP') > 0 .and. parsed%find('-FUP') > 0) then
         call set_error(error, 'SET FUP / -FUP: give one of them, not both')
         return
      end if
      call zpress_check(ctx%model, parsed, error)
      if (allocated(error)) return
      do k = 1, parsed%nitems
         select case (parsed%items(k)%name)
         case ('')
         case ('LOG')
            call set_log(ctx, want_log, error)
            if (allocated(error)) return
            ! the cutting commands' per-cut notes go to the log as well
            ctx%out%detail = want_log
         case ('GRAVITY')
            call handle_gravity(ctx%model, parsed%real_at(k, 1), parsed%real_at(k, 2))
         case ('XFORM')
            call set_xform(parsed, k, error)
            if (allocated(error)) return
         case ('PLOT', 'PS', 'PNG', 'HP', 'SPERRY', 'OUTPUT', 'CGA', 'EGA', 'MONO', 'CHAR', &
               'XYWRITE')
            call set_plot_keyword(ctx%plot, parsed, k, ctx%out, error)
            if (allocated(error)) return
         case ('SEED', 'EDGE', 'JMATDF', 'JCONDF')
            call set_geometry_keyword(ctx%model, parsed, k, handled, error)
            if (allocated(error)) return
         case ('CSCAN', 'DSCAN', 'UPCON', 'OVTOL', 'CLEMIN')
            call set_mechanics_keyword(ctx%model, parsed, k, handled)
         case ('FUP', '-FUP')
            call boundary_set_fup(ctx%model, parsed%items(k)%name == 'FUP', ctx%out)
         case ('ZPRESS')
            call zpress_set(ctx%model, parsed, k, ctx%out, error)
            if (allocated(error)) return
         case ('CAPRATIO', 'SFLOW', '-SFLOW', 'EFF', '-EFF', 'YWTABLE', 'PTOL')
            if (is_fluid_set_keyword(parsed%items(k)%name)) &
               call set_fluid_keyword(ctx%model, parsed, k)
         case ('THDT', 'NTHER', 'NMECH')
            if (is_thermal_set_keyword(parsed%items(k)%name)) &
               call set_thermal_keyword(ctx%model, parsed, k)
         case ('ON', 'OFF')
            if (k > 2) cycle     ! the value of the keyword before it (LOG, XFORM)
            call set_error(error, 'SET '//parsed%items(k)%name// &
                           ': expected a keyword such as LOG or XFORM before it')
            return
         case default
            call ctx%out%line('*** SET '//parsed%items(k)%name//': not yet implemented')
         end select
      end do
   end subroutine do_set

   !> SET LOG ON opens UDEC.LOG (overwritten the first time in a ctx, appended
   !> after a later ON, as the manual says); OFF stops logging without closing.
   subroutine set_log(ctx, on, error)
      type(context_t), intent(inout) :: ctx
      logical, intent(in) :: on
      type(error_t), allocatable, intent(out) :: error
      integer :: ios
      if (on) then
         if (.not. ctx%log_opened) then
            open (newunit=ctx%log_unit, file='UDEC.LOG', status='replace', &
                  action='write', iostat=ios)
            if (ios /= 0) then
               call set_error(error, 'SET LOG: cannot open UDEC.LOG for writing')
               return
            end if
            ctx%log_opened = .true.
         end if
         if (.not. ctx%log_on) call ctx%out%add_unit(ctx%log_unit)
         ctx%log_on = .true.
      else if (ctx%log_on) then
         call ctx%out%remove_unit(ctx%log_unit)
         ctx%log_on = .false.
      end if
   end subroutine set_log

end module commands_control
