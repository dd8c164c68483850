!> The commands of the session itself (manual Section 4.5): STOP, QUIT, END,
!> HEADING, CALL, RETURN, START, NEW and SET. SET's keywords are registered
!> and handled by the family of each (SET LOG here, SET ZPRESS in
!> commands_zpress, ..); they are checked, then act in order. HELP (not in the manual) prints the
!> command reference from the registry.
module commands_control
   use core_error, only: error_t, set_error
   use model_state, only: model_reset
   use model_geometry, only: rjoint_file
   use geometry_cutting, only: rjoint_on, rjoint_traces
   use commands_parser, only: parsed_t
   use commands_context, only: context_t, registry_t, context_push_file, context_pop_source, &
                               cannot_fail, set_handler
   use commands_source, only: source_read_raw
   use engine_stages, only: cycle_report_t
   use commands_tokens, only: printable
   use commands_grammar, only: match_none, match_ambiguous
   use commands_help, only: help_list, help_command
   use commands_print, only: print_settings
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
      call reg%add('control', 'HEading', 't*', '', '', '4.5', &
                   'the next input line is the title of the problem (udec: or the words ' &
                   //'after HEADING on its own line)', run_heading, &
                   in_check=.true.)
      call reg%add('control', 'CALL', 's', '', '', '4.5', &
                   'read commands from a file (RETURN comes back)', run_call)
      call reg%add('control', 'RETurn', '', '', '', '4.5', &
                   'leave a CALLed file, back to the caller', run_return)
      call reg%add('control', 'Start', '', '', '', '4.5', 'start a new problem (as NEW)', run_new)
      call reg%add('control', 'NEW', '', '', '', '4.5', 'start a new problem: the model is empty', &
                   run_new)
      ! SET's keywords are registered by the family of each (add_set)
      call reg%add('control', 'SEt', '', '', '', '4.5', &
                   'program settings: contact scans, tolerances, log, plot route, ..', do_set)
      call reg%add_set('control', 'Log;ON;OFF', set_control)
      call reg%add_set('control', 'Write;-Write', set_write)
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
      character(len=:), allocatable :: title
      ! udec extension: words after HEADING on its line are the title (a new
      ! user writes `HEAD my model`); the manual's form reads the next line
      if (parsed%nvalues > 0) then
         title = ' '//parsed%values(1)%text
         if (.not. ctx%check_only) ctx%model%heading = printable_heading(title)
         return
      end if
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

   !> SET: every keyword of the line is checked by its family's handler, then
   !> they act in order; a keyword registered without a handler says so. SET
   !> alone prints the settings.
   subroutine do_set(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer :: k, pass, g
      procedure(set_handler), pointer :: handler
      ! SET alone: the settings and their values (as PRINT STATUS ends)
      if (.not. any(parsed%items(1:parsed%nitems)%keyword > 0)) then
         call print_settings(ctx%model, ctx%out)
         return
      end if
      do pass = 1, 2
         do k = 1, parsed%nitems
            if (parsed%items(k)%keyword <= 0) cycle
            g = ctx%registry%find_set(parsed%items(k)%name)
            handler => null()
            if (g > 0) then
               handler => ctx%registry%set_keywords(g)%handler
               if (associated(ctx%registry%set_keywords(g)%act)) then
                  if (pass == 2) call ctx%registry%set_keywords(g)%act(ctx%model, parsed, k)
                  cycle
               end if
            end if
            if (.not. associated(handler)) then
               if (pass == 2) call ctx%out%line('*** SET '//parsed%items(k)%name// &
                                                ': not yet implemented')
               cycle
            end if
            call handler(ctx, parsed, k, pass == 2, error)
            if (allocated(error)) return
         end do
      end do
   end subroutine do_set

   !> SET LOG ON | OFF, and ON / OFF as the value of the keyword before them.
   subroutine set_control(ctx, parsed, k, apply, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k
      logical, intent(in) :: apply
      type(error_t), allocatable, intent(out) :: error
      integer :: first
      logical :: want_log
      select case (parsed%items(k)%name)
      case ('LOG')
         ! LOG must be followed by ON or OFF; the first LOG of the line decides
         first = parsed%find('LOG')
         want_log = .false.
         if (first < parsed%nitems) then
            select case (parsed%items(first + 1)%name)
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
         if (.not. apply) return
         call set_log(ctx, want_log, error)
         if (allocated(error)) return
         ! the cutting commands' per-cut notes go to the log as well
         ctx%out%detail = want_log
      case ('ON', 'OFF')
         if (.not. apply) return
         if (k > 2) return     ! the value of the keyword before it (LOG, XFORM)
         call set_error(error, 'SET '//parsed%items(k)%name// &
                        ': expected a keyword such as LOG or XFORM before it')
      end select
   end subroutine set_control

   !> SET WRITE: from now on the joint traces of CRACK and JSET (the 1989
   !> program's "scratch" joint file) are written to RJOINT, which starts
   !> anew here; SET -WRITE (the default) stops it.
   subroutine set_write(ctx, parsed, k, apply, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k
      logical, intent(in) :: apply
      type(error_t), allocatable, intent(out) :: error
      integer :: u, ios
      if (.not. apply) return
      if (parsed%items(k)%name == '-WRITE') then
         rjoint_on = .false.
         rjoint_traces%n = 0
         call ctx%out%line('SET -WRITE: joint traces are no longer written to '//rjoint_file)
         return
      end if
      open (newunit=u, file=rjoint_file, status='replace', action='write', iostat=ios)
      if (ios /= 0) then
         call set_error(error, 'SET WRITE: cannot write the file '//rjoint_file)
         return
      end if
      write (u, '(a)') '* RJOINT (SET WRITE): joint traces of CRACK and JSET inside the ' // &
         'blocks: x1 y1 x2 y2 block'
      close (u)
      rjoint_on = .true.
      rjoint_traces%n = 0
      call ctx%out%line('SET WRITE: the joint traces of CRACK and JSET go to '//rjoint_file)
   end subroutine set_write

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
