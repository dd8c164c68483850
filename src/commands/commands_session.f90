!> The command interpreter: reads logical lines from a stack of sources (the
!> batch file or prompt, UDEC.INI, CALLed files), parses each against the
!> grammar and runs the handler the command's family registered for it
!> (commands_catalog). Input errors are reported with file and line; in
!> batch mode the first one ends the run with a non-zero status, interactively
!> the session goes on. A rejected command never changes the model.
module commands_session
   use core_kinds, only: wp
   use core_error, only: error_t, set_error
   use core_output, only: output_t, itoa
   use core_interrupt, only: interrupt_busy, interrupt_clear, interrupt_pending, &
                             interrupt_signal, signal_interrupt
   use model_state, only: model_t, model_reset
   use commands_tokens, only: token_t, tokenize, printable
   use commands_parser, only: parsed_t, parse_command, value_real
   use commands_help, only: usage_text, argument_name
   use commands_plot, only: plot_session_end
   ! session_push_file: push a file source (commands_context's CALL does the
   ! same); `defaults` marks the start-up file UDEC.INI
   use commands_context, only: session_t => context_t, command_handler, &
                               context_pop_source, max_call_depth, &
                               session_push_file => context_push_file
   use commands_catalog, only: catalog_build
   use commands_source, only: source_open_stdin, source_read_logical
   use model_address, only: address_sync
   use model_compact, only: model_compact_corners
   use commands_address, only: addresses_current
   use contact_domains, only: domains_for_sync, domains_released
   use core_lineedit, only: lineedit_active, lineedit_add_word
   use core_memory, only: memory_policy
   implicit none
   private
   public :: session_t, session_init, session_push_file, session_push_stdin, session_run
   public :: session_finish, max_call_depth, session_execute_line, search_kept

contains

   subroutine session_init(session, error)
      type(session_t), intent(out) :: session
      type(error_t), allocatable, intent(out) :: error
      call memory_policy()
      call catalog_build(session%registry, session%grammar, error)
      call model_reset(session%model)
   end subroutine session_init

   subroutine session_push_stdin(session)
      type(session_t), intent(inout) :: session
      integer :: i, k, a, b
      session%depth = session%depth + 1
      call source_open_stdin(session%sources(session%depth))
      if (.not. lineedit_active()) return
      ! tab completion: every command's name and keywords (the registry)
      do i = 1, session%registry%n
         associate (e => session%registry%entries(i))
            call lineedit_add_word(e%name)
            if (.not. allocated(e%keywords)) cycle
            a = 1
            do while (a <= len(e%keywords))
               b = index(e%keywords(a:), ';')
               b = merge(len(e%keywords), a + b - 2, b == 0)
               k = index(e%keywords(a:b), ' ')
               if (k == 0) then
                  call lineedit_add_word(e%keywords(a:b))
               else
                  call lineedit_add_word(e%keywords(a:a + k - 2))
               end if
               a = b + 2
            end do
         end associate
      end do
   end subroutine session_push_stdin

   subroutine pop_source(session)
      type(session_t), intent(inout) :: session
      call context_pop_source(session)
   end subroutine pop_source

   !> Run until STOP, end of all input, or (batch) the first input error.
   subroutine session_run(session)
      type(session_t), intent(inout) :: session
      character(len=:), allocatable :: code
      integer :: first_line, depth
      logical :: eof, too_long
      do while (session%depth > 0 .and. .not. session%stopped)
         call source_read_logical(session%sources(session%depth), session%out, 'UDEC> ', &
                                  code, first_line, eof, too_long)
         if (eof) then
            ! a file that is not text (a NUL byte, an endless line) is
            ! reported at its line and read no further
            if (allocated(session%sources(session%depth)%fault)) then
               depth = session%depth
               call report(session, session%sources(session%depth)%fault, &
                           session%sources(session%depth)%line + 1)
               ! at the prompt, report has left the file already
               if (session%depth < depth) cycle
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
      call session%out%line('Interrupted: back at the prompt (a CYCLE, SOLVE or RUN keeps its '// &
                            'last complete step; any other command left the model as before it).')
   end subroutine after_interrupt

   !> Parse and execute one logical line (comments already removed).
   subroutine session_execute_line(session, code, line_number)
      type(session_t), intent(inout) :: session
      character(len=*), intent(in) :: code
      integer, intent(in) :: line_number
      type(token_t), allocatable :: tokens(:)
      integer :: ntokens, k
      character(len=:), allocatable :: name
      logical :: after_range
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
         ! an argument is missing: say which arguments the command takes
         ! (the last item read is the one short of arguments: a keyword's name,
         ! or '' for the positional arguments, which gives the command's syntax)
         if (index(error%message, '(line ended)') > 0 .and. parsed%command > 0) &
            error%message = error%message//'; '// &
                            usage_text(session%registry, session%grammar, parsed%command, &
                                       parsed%items(parsed%nitems)%name)
         ! a wrong positional argument: say which one and the syntax
         ! (STRUCTURE's npoin typed 0.1: "expected an integer >= 1, got '0.1'")
         if (index(error%message, ", got '") > 0 .and. parsed%command > 0 .and. &
             parsed%nitems == 1) then
            k = index(error%message, ': ')
            ! a range is read apart from the numbers counted (LOAD R r r)
            after_range = index(session%grammar%commands(parsed%command)%positional, 'R') == 1
            name = argument_name(session%registry%entries(parsed%command), &
                                 parsed%items(1)%count + 1, after_range)
            if (len(name) > 0) name = ' ('//name//')'
            ! a range's own error names the range, not its first word
            if (index(error%message, 'range expects') > 0) name = ''
            if (after_range) name = ' after the range'//name
            if (k > 0) error%message = error%message(1:k)//' argument '// &
                                       itoa(parsed%items(1)%count + 1)//name//':'// &
                                       error%message(k + 1:)//'; '// &
                                       usage_text(session%registry, session%grammar, &
                                                  parsed%command, '')
         end if
         call report(session, error%message, line_number)
         return
      end if
      call dispatch(session, parsed, error)
      if (.not. allocated(error)) return
      ! a long command (GENERATE, JSET, SAVE) that polls for Ctrl-C / SIGTERM
      ! stops with an error and the model as before it: not an input error;
      ! after_interrupt then decides what follows
      if (interrupt_pending()) then
         call session%out%line('*** '//error%message)
         return
      end if
      call report(session, error%message, line_number, error%numerical)
   end subroutine session_execute_line

   !> Print an input error (or a numerical failure of the calculation,
   !> `numerical`) with its location; in batch mode, end the run.
   subroutine report(session, message, line_number, numerical)
      type(session_t), intent(inout) :: session
      character(len=*), intent(in) :: message
      integer, intent(in) :: line_number
      logical, intent(in), optional :: numerical
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
      if (.not. session%batch) call skip_called_files(session, line_number)
      if (session%batch .and. .not. session%check_only) then
         session%stopped = .true.
         session%exit_status = 1
         if (present(numerical)) then
            if (numerical) then
               call session%out%line('*** Run stopped because the calculation failed (above); '// &
                                     'the rest of the deck is skipped.')
               return
            end if
         end if
         call session%out%line('*** Run stopped because of the input error above.')
      end if
   end subroutine report

   !> At the prompt, an error in a CALLed file (an input error, or a CYCLE
   !> that failed) ends the reading of that file and of the files that CALLed
   !> it: their later commands were written for a model the failed line did
   !> not make (a CYCLE 5000 after a refused BOUNDARY). Back at the prompt, the
   !> model is as after the last good command; the user fixes the line and
   !> CALLs again or goes on by hand. (In a batch run the first error ends
   !> the run; UDEC.INI skips its bad lines: report.)
   subroutine skip_called_files(session, line_number)
      type(session_t), intent(inout) :: session
      integer, intent(in) :: line_number
      character(len=32) :: num
      if (session%depth <= 1) return
      if (session%sources(session%depth)%interactive) return
      write (num, '(i0)') line_number
      call session%out%line('    the rest of '//session%sources(session%depth)%name// &
                            ' (after line '//trim(num)//') is not read: back at the prompt, '// &
                            'the model as after the last good command')
      do while (session%depth > 1)
         if (session%sources(session%depth)%interactive) exit
         call pop_source(session)
      end do
   end subroutine skip_called_files

   !> Run the handler registered for the parsed command. Under `udec --check`
   !> only the commands that steer the reading run (STOP, HEADING).
   subroutine dispatch(session, parsed, error)
      type(session_t), intent(inout) :: session
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      procedure(command_handler), pointer :: handler
      if (session%check_only .and. .not. session%registry%entries(parsed%command)%in_check) return
      handler => session%registry%entries(parsed%command)%handler
      if (.not. associated(handler)) then
         call session%out%line('*** '//parsed%name//': not yet implemented')
         return
      end if
      call refuse_huge_values(parsed, error)
      if (allocated(error)) return
      ! GENERATE adds gridpoint and zone records: the contacts and domains the
      ! cuts before it made get theirs first; PRINT and PLOT show them
      ! (model_address).
      select case (parsed%name)
      case ('GENERATE', 'PRINT', 'PLOT')
         call addresses_current(session%model)
      case ('SAVE')
         ! the file holds the domains: those a dry CYCLE gave back are built
         ! from the contacts now and take their records (contact_domains)
         if (domains_released(session%model%geometry)) call addresses_current(session%model)
      end select
      call handler(session, parsed, error)
      if (.not. search_kept(parsed%name)) then
         session%model%mech%search_current = .false.
         ! what the last search found stands for the blocks a local cut
         ! leaves alone (engine_cycle search_base); after any other command
         ! the next search looks at every pair
         if (.not. cuts_locally(parsed%name)) session%model%mech%search_sizes = -1
      end if
      call addresses_after(session%model)
   end subroutine dispatch

   !> Commands after which the last search for new contacts still stands
   !> (model_mechanics, search_current; engine_cycle, search_skippable).
   !> The search finds the corners within the contact margin of another
   !> block: it reads the blocks' corners and rings, the contacts already
   !> there, the rounding and the model's extent (contact_margin), and
   !> nothing else (no material, joint property, fixity, load or boundary
   !> condition). Kept: the commands that read or write the model out, steer
   !> the reading, record histories or set the damping and the step (which
   !> the set-up of the next CYCLE recomputes), and those that set loads,
   !> fixities, boundary conditions, properties and stresses (FIX, FREE,
   !> LOAD, PROPERTY, GRAVITY, BOUNDARY, INSITU, MSCALE, PFIX, PFREE and the
   !> thermal conditions; Issue 23): none of them moves, cuts or deletes a
   !> block or corner, makes or kills a contact or changes ROUND or EDGE,
   !> and a block they set moving is followed by the travel since the last
   !> search. Every other command makes the next CYCLE search: those that
   !> cut, delete, move or round blocks (JSET, SPLIT, CRACK, TUNNEL, ARC,
   !> DELETE, JDELETE, BLOCK, ROUND, EDGE, GENERATE ...), and those this list
   !> has not been shown to be safe for (CHANGE, SET, RSET, RESET, the
   !> structures ...). RESTART is kept: it reads the state of the last search
   !> from its file (schema 17).
   pure logical function search_kept(name)
      character(len=*), intent(in) :: name
      select case (name)
      case ('CYCLE', 'SOLVE', 'PRINT', 'PLOT', 'HISTORY', 'THIST', 'SAVE', 'RESTART', 'DUMP', &
            'EXPORT', 'WINDOW', 'HEADING', 'HELP', 'CALL', 'RETURN', 'STOP', 'END', 'QUIT', 'DAMPING', &
            'FRACTION', 'TABLE')
         search_kept = .true.
      case ('FIX', 'FREE', 'LOAD', 'PROPERTY', 'GRAVITY', 'BOUNDARY', 'INSITU', 'MSCALE', 'PFIX', &
            'PFREE', 'TFIX', 'TFREE', 'INITEM', 'THAPP')
         search_kept = .true.
      case default
         search_kept = .false.
      end select
   end function search_kept

   !> Commands that change the geometry only by cutting, deleting or
   !> re-ringing blocks: every block they change gets a new corner ring
   !> (geometry_set_block_polygon appends it) or dies; the corners of the
   !> others, their rounding and the margin stay (what geometry_round_facing
   !> caps is seen in geometry_refresh). After them a cycled model's next
   !> search need only look at the pairs with a changed block
   !> (engine_cycle search_base).
   pure logical function cuts_locally(name)
      character(len=*), intent(in) :: name
      select case (name)
      case ('JSET', 'CRACK', 'TUNNEL', 'ARC', 'DELETE', 'SPLIT')
         cuts_locally = .true.
      case default
         cuts_locally = .false.
      end select
   end function cuts_locally

   !> Commands whose numbers become stresses, loads, velocities or material
   !> stiffnesses, moduli and densities refuse a magnitude beyond 1e15
   !> before they change anything:
   !> squares and products of such a number overflow in the cycle (a trap in
   !> the Debug build, NaN in Release), as BOUNDARY's did (commands_boundary).
   !> The error names the command, the keyword and the number. A range
   !> (xl xu yl yu) is not a value and is not limited.
   subroutine refuse_huge_values(parsed, error)
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: max_value = 1.0e15_wp
      character(len=16) :: text
      character(len=:), allocatable :: word
      integer :: k, j
      select case (parsed%name)
      case ('INSITU', 'LOAD', 'PROPERTY', 'GRAVITY', 'FIX')
      case default
         return
      end select
      do k = 1, parsed%nvalues
         if (parsed%values(k)%kind /= value_real) cycle
         if (abs(parsed%values(k)%r) <= max_value) cycle
         word = ''
         do j = 1, parsed%nitems
            if (k >= parsed%items(j)%first .and. k < parsed%items(j)%first + parsed%items(j)%count) then
               if (allocated(parsed%items(j)%name)) word = parsed%items(j)%name
            end if
         end do
         ! PROPERTY: the stiffnesses, moduli and density (a strength of 1e120
         ! stands for "unbreakable" and is only ever compared)
         if (parsed%name == 'PROPERTY') then
            select case (word)
            case ('K', 'BULK', 'G', 'SHEAR', 'D', 'DENSITY', 'JKN', 'JKS', 'KN', 'KS')
            case default
               cycle
            end select
         end if
         write (text, '(es12.4e3)') parsed%values(k)%r
         if (len(word) > 0) word = ' '//word
         call set_error(error, parsed%name//':'//word//' '//trim(adjustl(text)) &
                        //' is too large (a stress, load, velocity or property of at most 1E+15)')
         return
      end do
   end subroutine refuse_huge_values

   !> 1989 addresses (model_address) of what the command created. While the
   !> set-up's contacts are out of date (a cut since the last rebuild) their
   !> records and the domains' wait for the next command that brings them up
   !> to date (GENERATE, PRINT, PLOT, CYCLE, the commands that take an
   !> address): a rebuild per cut would cost more than the cuts. Bookkeeping only: the cycle never
   !> reads the addresses.
   subroutine addresses_after(model)
      type(model_t), intent(inout) :: model
      if (.not. model%geometry%block_created) return
      ! domains given back by a dry CYCLE: built again if a contact was made
      ! or broken since the last synchronisation (contact_domains)
      call domains_for_sync(model%geometry)
      call address_sync(model%geometry, blocks_only=.not. model%geometry%mechanical .and. &
                        (.not. model%geometry%contacts_valid .or. .not. model%geometry%domains_valid))
      ! the corners the command killed have given their records back: the
      ! live ones take ids 1..n (model_compact; a restored file's too)
      call model_compact_corners(model)
   end subroutine addresses_after


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
