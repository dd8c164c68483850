!> The command interpreter: reads logical lines from a stack of sources (the
!> batch file or prompt, UDEC.INI, CALLed files), parses each against the
!> grammar and dispatches it. Input errors are reported with file and line; in
!> batch mode the first one ends the run with a non-zero status, interactively
!> the session goes on. A rejected command never changes the model.
module commands_session
   use core_error, only: error_t, set_error
   use core_output, only: output_t
   use core_interrupt, only: interrupt_busy, interrupt_clear, interrupt_pending, &
                             interrupt_signal, signal_interrupt
   use core_files, only: check_input_file
   use model_state, only: model_t, model_reset
   use commands_tokens, only: token_t, tokenize, printable
   use commands_grammar, only: grammar_t, grammar_build
   use commands_be, only: do_be
   use commands_parser, only: parsed_t, parse_command
   use commands_properties, only: handle_property, handle_gravity
   use commands_geometry, only: handle_geometry_command, set_geometry_keyword, &
                                remove_partial_cracks_once
   use commands_geometry_extras, only: handle_jplot, handle_link
   use commands_print, only: handle_print
   use commands_mechanics, only: handle_mechanics_command, set_mechanics_keyword
   use commands_plot, only: plot_state_t, handle_plot, handle_copy, handle_window, &
                            set_plot_keyword, plot_session_end
   use commands_io, only: handle_save, handle_restart, set_xform
   use commands_zones, only: do_generate
   use commands_structure, only: handle_structure
   use commands_boundary, only: do_boundary, do_insitu, boundary_set_fup
   use commands_zpress, only: zpress_check, zpress_set
   use commands_thermal, only: handle_thermal_command, is_thermal_set_keyword, &
                               set_thermal_keyword
   use commands_fluid, only: handle_fluid, handle_pfix, handle_pfree, set_fluid_keyword, &
                             is_fluid_set_keyword
   use commands_source, only: source_t, source_open_file, source_open_stdin, source_close, &
                              source_read_logical, source_read_raw
   implicit none
   private
   public :: session_t, session_init, session_push_file, session_push_stdin, session_run
   public :: session_finish, max_call_depth, session_execute_line

   !> CALL nesting: the manual allowed one level; we allow this many sources.
   integer, parameter :: max_call_depth = 8

   type :: session_t
      type(grammar_t) :: grammar
      type(model_t) :: model
      type(output_t) :: out
      integer :: depth = 0
      type(source_t) :: sources(max_call_depth)
      logical :: batch = .false.        !< an input error ends the run
      logical :: check_only = .false.   !< parse only (udec --check)
      logical :: stopped = .false.
      integer :: nerrors = 0
      integer :: exit_status = 0
      integer :: log_unit = -1
      logical :: log_opened = .false.
      logical :: log_on = .false.
      type(plot_state_t) :: plot        !< window, plot route, last picture
   end type session_t

contains

   subroutine session_init(session, error)
      type(session_t), intent(out) :: session
      type(error_t), allocatable, intent(out) :: error
      call grammar_build(session%grammar, error)
      call model_reset(session%model)
   end subroutine session_init

   !> Push a file source. `called` marks a CALLed file (RETURN may leave it).
   !> `defaults` marks the start-up file UDEC.INI (errors there do not stop a run).
   subroutine session_push_file(session, name, error, defaults)
      type(session_t), intent(inout) :: session
      character(len=*), intent(in) :: name
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: defaults
      integer :: k
      logical :: ok
      do k = 1, session%depth
         if (session%sources(k)%name == name) then
            call set_error(error, "CALL: file '"//name// &
                           "' is already being read (recursive CALL)")
            return
         end if
      end do
      if (session%depth >= max_call_depth) then
         call set_error(error, "CALL: too many nested files (at most 8 sources), cannot read '" &
                        //name//"'")
         return
      end if
      ! a folder or a device (CALL ., CALL /dev/zero) is not a command file
      call check_input_file(trim(merge('CALL', '    ', session%depth > 0)), name, error)
      if (allocated(error)) return
      call source_open_file(session%sources(session%depth + 1), name, ok)
      if (.not. ok) then
         call set_error(error, "cannot open file '"//name//"'")
         return
      end if
      session%sources(session%depth + 1)%echo = .not. session%check_only
      if (present(defaults)) session%sources(session%depth + 1)%defaults = defaults
      session%depth = session%depth + 1
   end subroutine session_push_file

   subroutine session_push_stdin(session)
      type(session_t), intent(inout) :: session
      session%depth = session%depth + 1
      call source_open_stdin(session%sources(session%depth))
   end subroutine session_push_stdin

   subroutine pop_source(session)
      type(session_t), intent(inout) :: session
      call source_close(session%sources(session%depth))
      session%depth = session%depth - 1
   end subroutine pop_source

   !> Run until STOP, end of all input, or (batch) the first input error.
   subroutine session_run(session)
      type(session_t), intent(inout) :: session
      character(len=:), allocatable :: code
      integer :: first_line
      logical :: eof, too_long
      do while (session%depth > 0 .and. .not. session%stopped)
         call source_read_logical(session%sources(session%depth), session%out, 'UDEC> ', &
                                  code, first_line, eof, too_long)
         if (eof) then
            ! a file that is not text (a NUL byte, an endless line) is
            ! reported at its line and read no further
            if (allocated(session%sources(session%depth)%fault)) then
               call report(session, session%sources(session%depth)%fault, &
                           session%sources(session%depth)%line + 1)
            end if
            call pop_source(session)
            cycle
         end if
         if (session%sources(session%depth)%interactive .and. session%log_on) then
            write (session%log_unit, '(a)') 'UDEC> '//trim(adjustl(code))
         end if
         if (too_long) then
            call report(session, 'input line is too long (more than 1000000 characters)', &
                        first_line)
            cycle
         end if
         ! a Ctrl-C typed at the prompt, before this command, is forgotten
         call interrupt_busy(.true.)
         if (.not. session%batch) call interrupt_clear()
         call session_execute_line(session, code, first_line)
         call interrupt_busy(.false.)
         if (interrupt_pending()) call after_interrupt(session)
      end do
      if (session%stopped) then
         do while (session%depth > 0)
            call pop_source(session)
         end do
      end if
   end subroutine session_run

   !> A signal arrived while a command ran (its CYCLE or RUN has stopped at
   !> the end of a step). Interactively, Ctrl-C goes back to the UDEC> prompt,
   !> leaving any CALLed file; in a batch run, or on SIGTERM, the rest of the
   !> input is skipped and the program ends with status 128 + the signal.
   subroutine after_interrupt(session)
      type(session_t), intent(inout) :: session
      integer :: signal
      character(len=16) :: name
      signal = interrupt_signal()
      call interrupt_clear()
      name = 'SIGTERM'
      if (signal == signal_interrupt) name = 'SIGINT (Ctrl-C)'
      if (session%batch .or. signal /= signal_interrupt) then
         call session%out%line('*** Interrupted by '//trim(name)// &
                               ': the rest of the input is skipped; the run ends here.')
         session%stopped = .true.
         session%exit_status = 128 + signal
         return
      end if
      do while (session%depth > 1)
         if (session%sources(session%depth)%interactive) exit
         call pop_source(session)
      end do
      call session%out%line('Interrupted: back at the prompt; the model is as after the '// &
                            'last complete step.')
   end subroutine after_interrupt

   !> Parse and execute one logical line (comments already removed).
   subroutine session_execute_line(session, code, line_number)
      type(session_t), intent(inout) :: session
      character(len=*), intent(in) :: code
      integer, intent(in) :: line_number
      type(token_t), allocatable :: tokens(:)
      integer :: ntokens
      type(parsed_t) :: parsed
      type(error_t), allocatable :: error
      call tokenize(code, tokens, ntokens)
      if (ntokens == 0) return
      if (tokens(1)%text(1:1) == '+') then
         call report(session, "a line starting with '+' continues the previous line; " // &
                     "this works only in files (use '&' at the end of the line instead)", &
                     line_number)
         return
      end if
      call parse_command(session%grammar, code, tokens, ntokens, parsed, error)
      if (allocated(error)) then
         call report(session, error%message, line_number)
         return
      end if
      call dispatch(session, parsed, error)
      if (allocated(error)) call report(session, error%message, line_number)
   end subroutine session_execute_line

   !> Print an input error with its location; in batch mode, end the run.
   subroutine report(session, message, line_number)
      type(session_t), intent(inout) :: session
      character(len=*), intent(in) :: message
      integer, intent(in) :: line_number
      character(len=32) :: num
      session%nerrors = session%nerrors + 1
      call session%out%line('*** Error: '//message)
      if (session%depth > 0) then
         if (.not. session%sources(session%depth)%interactive) then
            write (num, '(i0)') line_number
            call session%out%line('    in file '//session%sources(session%depth)%name// &
                                  ', line '//trim(num))
         end if
      end if
      ! manual 4.3: UDEC.INI holds site defaults read on start-up; a bad line
      ! there (or in a file it CALLs) is reported and skipped, the deck still runs
      if (session%depth > 0) then
         if (any(session%sources(1:session%depth)%defaults)) then
            call session%out%line('    (UDEC.INI: this line is skipped; the run goes on)')
            return
         end if
      end if
      if (session%batch .and. .not. session%check_only) then
         session%stopped = .true.
         session%exit_status = 1
         call session%out%line('*** Run stopped because of the input error above.')
      end if
   end subroutine report

   !> Execute a parsed command.
   subroutine dispatch(session, parsed, error)
      type(session_t), intent(inout) :: session
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      logical :: handled
      select case (parsed%name)
      case ('STOP', 'QUIT', 'END')
         session%stopped = .true.
      case ('HEADING')
         call do_heading(session, error)
      case ('CALL')
         if (session%check_only) return
         call session_push_file(session, parsed%text_at(1, 1), error)
      case ('RETURN')
         if (session%check_only) return
         if (session%depth <= 1 .or. session%sources(session%depth)%interactive) then
            call set_error(error, 'RETURN: not inside a CALLed file')
            return
         end if
         call pop_source(session)
      case default
         if (session%check_only) return
         select case (parsed%name)
         case ('START', 'NEW')
            call model_reset(session%model)
            call session%out%line('New problem: the model is empty.')
         case ('SET')
            call do_set(session, parsed, error)
         case ('PROPERTY')
            call handle_property(session%model, parsed, error, session%out)
         case ('GRAVITY')
            call handle_gravity(session%model, parsed%real_at(1, 1), parsed%real_at(1, 2))
         case ('PRINT')
            call do_print(session, parsed, error)
         case ('SAVE')
            call handle_save(session%model, parsed, session%out, error)
         case ('RESTART')
            call handle_restart(session%model, parsed, session%out, error)
         case ('BOUNDARY')
            call do_boundary(session%model, parsed, session%out, error)
         case ('BE')
            call do_be(session%model, parsed, session%out, error)
         case ('INSITU')
            call do_insitu(session%model, parsed, session%out, error)
         case ('JPLOT')
            call handle_jplot(session%model, parsed, session%out, error)
         case ('LINK')
            call handle_link(session%model, parsed, session%out, error)
         case ('PLOT')
            call handle_plot(session%plot, session%model, parsed, session%batch, session%out, &
                             error)
         case ('COPY')
            call handle_copy(session%plot, parsed, session%out, error)
         case ('WINDOW')
            call handle_window(session%plot, session%model, parsed, session%out, error)
         case ('GENERATE')
            call do_generate(session%model, parsed, session%out, error)
         case ('STRUCTURE')
            call handle_structure(session%model, parsed, session%out, error)
         case ('FLUID')
            call handle_fluid(session%model, parsed, session%out, error)
         case ('PFIX')
            call handle_pfix(session%model, parsed, session%out, error)
         case ('PFREE')
            call handle_pfree(session%model, parsed, session%out, error)
         case ('THERMAL', 'INITEM', 'TFIX', 'TFREE', 'THAPP', 'RUN', 'THIST')
            call handle_thermal_command(session%model, parsed, session%out, handled, error)
         case ('CYCLE')
            call remove_partial_cracks_once(session%model, session%out)
            call handle_mechanics_command(session%model, parsed, session%out, handled, error)
            if (.not. handled) call not_implemented(session, parsed%name)
         case default
            call handle_geometry_command(session%model, parsed, session%out, handled, error)
            if (.not. handled) call handle_mechanics_command(session%model, parsed, session%out, &
                                                             handled, error)
            if (.not. handled) call not_implemented(session, parsed%name)
         end select
      end select
   end subroutine dispatch

   !> PRINT: commands_print (docs/print.md).
   subroutine do_print(session, parsed, error)
      type(session_t), intent(inout) :: session
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      call handle_print(session%model, parsed, session%out, error)
   end subroutine do_print

   subroutine not_implemented(session, what)
      type(session_t), intent(inout) :: session
      character(len=*), intent(in) :: what
      call session%out%line('*** '//what//': not yet implemented')
   end subroutine not_implemented

   !> HEADING: the next input line is the title (prompt HEAD> interactively).
   subroutine do_heading(session, error)
      type(session_t), intent(inout) :: session
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: text
      logical :: eof
      call source_read_raw(session%sources(session%depth), session%out, 'HEAD> ', text, eof)
      if (eof) then
         call set_error(error, 'HEADING: the title line is missing (end of input)')
         return
      end if
      if (session%check_only) return
      session%model%heading = printable_heading(text)
   end subroutine do_heading

   pure function printable_heading(text) result(clean)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: clean
      clean = trim(adjustl(text))
      if (len(clean) > 80) clean = clean(1:80)
   end function printable_heading

   !> SET: keywords act in order; those whose physics has not landed say so.
   subroutine do_set(session, parsed, error)
      type(session_t), intent(inout) :: session
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
      call zpress_check(session%model, parsed, error)
      if (allocated(error)) return
      do k = 1, parsed%nitems
         select case (parsed%items(k)%name)
         case ('')
         case ('LOG')
            call set_log(session, want_log, error)
            if (allocated(error)) return
            ! the cutting commands' per-cut notes go to the log as well
            session%out%detail = want_log
         case ('GRAVITY')
            call handle_gravity(session%model, parsed%real_at(k, 1), parsed%real_at(k, 2))
         case ('XFORM')
            call set_xform(parsed, k, error)
            if (allocated(error)) return
         case ('PLOT', 'PS', 'PNG', 'HP', 'SPERRY', 'OUTPUT', 'CGA', 'EGA', 'MONO', 'CHAR', &
               'XYWRITE')
            call set_plot_keyword(session%plot, parsed, k, session%out, error)
            if (allocated(error)) return
         case ('SEED', 'EDGE', 'JMATDF', 'JCONDF')
            call set_geometry_keyword(session%model, parsed, k, handled, error)
            if (allocated(error)) return
         case ('CSCAN', 'DSCAN', 'UPCON', 'OVTOL', 'CLEMIN')
            call set_mechanics_keyword(session%model, parsed, k, handled)
         case ('FUP', '-FUP')
            call boundary_set_fup(session%model, parsed%items(k)%name == 'FUP', session%out)
         case ('ZPRESS')
            call zpress_set(session%model, parsed, k, session%out, error)
            if (allocated(error)) return
         case ('CAPRATIO', 'SFLOW', '-SFLOW', 'EFF', '-EFF', 'YWTABLE', 'PTOL')
            if (is_fluid_set_keyword(parsed%items(k)%name)) &
               call set_fluid_keyword(session%model, parsed, k)
         case ('THDT', 'NTHER', 'NMECH')
            if (is_thermal_set_keyword(parsed%items(k)%name)) &
               call set_thermal_keyword(session%model, parsed, k)
         case ('ON', 'OFF')
            if (k > 2) cycle     ! the value of the keyword before it (LOG, XFORM)
            call set_error(error, 'SET '//parsed%items(k)%name// &
                           ': expected a keyword such as LOG or XFORM before it')
            return
         case default
            call not_implemented(session, 'SET '//parsed%items(k)%name)
         end select
      end do
   end subroutine do_set

   !> SET LOG ON opens UDEC.LOG (overwritten the first time in a session, appended
   !> after a later ON, as the manual says); OFF stops logging without closing.
   subroutine set_log(session, on, error)
      type(session_t), intent(inout) :: session
      logical, intent(in) :: on
      type(error_t), allocatable, intent(out) :: error
      integer :: ios
      if (on) then
         if (.not. session%log_opened) then
            open (newunit=session%log_unit, file='UDEC.LOG', status='replace', &
                  action='write', iostat=ios)
            if (ios /= 0) then
               call set_error(error, 'SET LOG: cannot open UDEC.LOG for writing')
               return
            end if
            session%log_opened = .true.
         end if
         if (.not. session%log_on) call session%out%add_unit(session%log_unit)
         session%log_on = .true.
      else if (session%log_on) then
         call session%out%remove_unit(session%log_unit)
         session%log_on = .false.
      end if
   end subroutine set_log

   subroutine session_finish(session)
      type(session_t), intent(inout) :: session
      if (.not. session%check_only) call plot_session_end(session%plot, session%batch, session%out)
      do while (session%depth > 0)
         call pop_source(session)
      end do
      if (session%log_opened) then
         if (session%log_on) call session%out%remove_unit(session%log_unit)
         close (session%log_unit)
         session%log_opened = .false.
         session%log_on = .false.
      end if
   end subroutine session_finish

end module commands_session
