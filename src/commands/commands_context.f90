!> The interpreter's state as handlers see it, and the command registry.
!>
!> Every command is registered once, by its family module (`register_*`): its
!> definition in the grammar notation of commands_grammar (name, positional,
!> loose and keyword specifications in the manual's casing), the manual
!> section, a one-line summary, notes on keywords (unit, default) and the
!> handler. Every handler has one interface, `(ctx, parsed, error)`. The
!> parser, `udec --check`, HELP and docs/commands.md all read this one table
!> (commands_catalog builds it, commands_help renders it).
!>
!> The registry is a value owned by the session context: no module state.
module commands_context
   use core_error, only: error_t, set_error
   use core_output, only: output_t
   use core_kinds, only: ip
   use core_files, only: check_input_file, case_match, file_kind, kind_missing
   use model_state, only: model_t
   use engine_cycle, only: cycle_report_t
   use commands_tokens, only: to_upper
   use commands_grammar, only: grammar_t
   use commands_parser, only: parsed_t
   use commands_source, only: source_t, source_open_file, source_close
   use commands_plot_state, only: plot_state_t
   implicit none
   private
   public :: context_t, registry_t, command_entry_t, keyword_note_t, command_handler
   public :: implemented, model_setter
   public :: set_keyword_t, set_handler
   public :: context_push_file, context_pop_source, max_call_depth, cannot_fail, require_block
   public :: warn_fdef_free, context_read_name

   !> CALL nesting: the manual allowed one level; we allow this many sources.
   integer, parameter :: max_call_depth = 8

   !> What the manual (or this program) says about one keyword's value.
   type :: keyword_note_t
      character(len=:), allocatable :: keyword   !< canonical (upper-case) keyword
      character(len=:), allocatable :: unit      !< SI unit of the value ('' unknown)
      character(len=:), allocatable :: default   !< value when not given ('' none)
      !> the positional arguments' names as the manual prints them, one word a
      !> number, optional ones in [ ] ('' none; keyword '' only): HELP and the
      !> usage of a parse error name them (`TUNNEL xc yc r n`)
      character(len=:), allocatable :: args
   end type keyword_note_t

   !> One command of the registry.
   type :: command_entry_t
      !> name in manual casing (capitals = minimum abbreviation)
      character(len=:), allocatable :: name
      character(len=:), allocatable :: positional  !< argument spec (commands_grammar)
      character(len=:), allocatable :: loose       !< spec of bare numbers among keywords
      character(len=:), allocatable :: keywords    !< `Name spec;Name spec;..`
      character(len=:), allocatable :: section     !< manual section, e.g. '4.5'
      character(len=:), allocatable :: summary     !< one line
      character(len=:), allocatable :: family      !< registering module, e.g. 'geometry'
      !> runs under `udec --check` too (STOP, HEADING: they steer the reading)
      logical :: in_check = .false.
      integer :: nnotes = 0
      type(keyword_note_t), allocatable :: notes(:)
      !> not associated: parsed and checked, then "not yet implemented"
      procedure(command_handler), pointer, nopass :: handler => null()
   end type command_entry_t

   !> Keywords of SET that one family registers, with their handler.
   type :: set_keyword_t
      character(len=:), allocatable :: family
      character(len=:), allocatable :: keywords   !< `Name spec;Name spec;..` (grammar notation)
      character(len=:), allocatable :: names      !< canonical names, `|SEED|EDGE|`
      !> neither associated: parsed and checked, then "not yet implemented"
      procedure(set_handler), pointer, nopass :: handler => null()
      !> keywords that need no check beyond the parser's: set on the model
      procedure(model_setter), pointer, nopass :: act => null()
   end type set_keyword_t

   !> The table of every command; entry i is command i of the grammar. SET's
   !> keywords come from the families too (add_set); commands_catalog joins
   !> them into SET's definition.
   type :: registry_t
      integer :: n = 0
      type(command_entry_t), allocatable :: entries(:)
      integer :: nset = 0
      type(set_keyword_t), allocatable :: set_keywords(:)
      type(keyword_note_t), allocatable :: set_notes(:)
      logical :: last_was_set = .false.   !< note() applies to SET keywords
   contains
      procedure :: add => registry_add
      procedure :: add_set => registry_add_set
      procedure :: note => registry_note
      procedure :: find => registry_find
      procedure :: find_set => registry_find_set
   end type registry_t

   !> What a handler may use: the model, the output, the session settings.
   type :: context_t
      type(registry_t) :: registry
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
      type(cycle_report_t) :: cycle     !< stages and their wall time (PRINT CYCLE)
   end type context_t

   abstract interface
      !> Execute one parsed command; a rejected command leaves the model unchanged.
      subroutine command_handler(ctx, parsed, error)
         import :: context_t, parsed_t, error_t
         type(context_t), intent(inout) :: ctx
         type(parsed_t), intent(in) :: parsed
         type(error_t), allocatable, intent(out) :: error
      end subroutine command_handler

      !> SET keyword item k: check it against the whole line (`apply` false:
      !> every keyword of the line is checked before any acts) or act.
      subroutine set_handler(ctx, parsed, k, apply, error)
         import :: context_t, parsed_t, error_t
         type(context_t), intent(inout) :: ctx
         type(parsed_t), intent(in) :: parsed
         integer, intent(in) :: k
         logical, intent(in) :: apply
         type(error_t), allocatable, intent(out) :: error
      end subroutine set_handler

      !> SET keyword item k acting on the model (after every keyword of the
      !> line was checked); for keywords the parser checks completely.
      subroutine model_setter(model, parsed, k)
         import :: model_t, parsed_t
         type(model_t), intent(inout) :: model
         type(parsed_t), intent(in) :: parsed
         integer, intent(in) :: k
      end subroutine model_setter
   end interface

contains

   !> Register a command. `name` in manual casing; the specifications in the
   !> notation of commands_grammar; `handler` absent: "not yet implemented".
   !> `unit`, `default` and `args` (names) of the positional arguments are
   !> their note (registry_note's keyword '').
   subroutine registry_add(this, family, name, positional, loose, keywords, section, summary, &
                           handler, in_check, unit, default, args)
      class(registry_t), intent(inout) :: this
      character(len=*), intent(in) :: family, name, positional, loose, keywords, section, summary
      procedure(command_handler), optional :: handler
      logical, intent(in), optional :: in_check
      character(len=*), intent(in), optional :: unit, default, args
      type(command_entry_t) :: e
      e%family = family
      e%name = name
      e%positional = positional
      e%loose = loose
      e%keywords = keywords
      e%section = section
      e%summary = summary
      if (present(in_check)) e%in_check = in_check
      allocate (e%notes(0))
      if (present(handler)) e%handler => handler
      if (.not. allocated(this%entries)) allocate (this%entries(0))
      this%entries = [this%entries, e]
      this%n = this%n + 1
      this%last_was_set = .false.
      if (present(unit) .or. present(default) .or. present(args)) &
         call this%note('', unit=unit, default=default, args=args)
   end subroutine registry_add

   !> Register keywords of SET (`Name spec;..`, grammar notation) and their
   !> handler: `handler` (the context, check and act) or `act` (the model).
   subroutine registry_add_set(this, family, keywords, handler, act)
      class(registry_t), intent(inout) :: this
      character(len=*), intent(in) :: family, keywords
      procedure(set_handler), optional :: handler
      procedure(model_setter), optional :: act
      type(set_keyword_t) :: group
      integer :: start, i, blank
      character(len=:), allocatable :: entry
      group%family = family
      group%keywords = keywords
      group%names = '|'
      start = 1
      do i = 1, len(keywords) + 1
         if (i <= len(keywords)) then
            if (keywords(i:i) /= ';') cycle
         end if
         entry = trim(adjustl(keywords(start:i - 1)))
         blank = index(entry, ' ')
         if (blank > 0) entry = entry(1:blank - 1)
         group%names = group%names//to_upper(entry)//'|'
         start = i + 1
      end do
      if (present(handler)) group%handler => handler
      if (present(act)) group%act => act
      if (.not. allocated(this%set_keywords)) allocate (this%set_keywords(0))
      if (.not. allocated(this%set_notes)) allocate (this%set_notes(0))
      this%set_keywords = [this%set_keywords, group]
      this%nset = this%nset + 1
      this%last_was_set = .true.
   end subroutine registry_add_set

   !> The SET keyword group that holds canonical keyword `name`, 0 if none.
   integer function registry_find_set(this, name) result(k)
      class(registry_t), intent(in) :: this
      character(len=*), intent(in) :: name
      do k = 1, this%nset
         if (index(this%set_keywords(k)%names, '|'//name//'|') > 0) return
      end do
      k = 0
   end function registry_find_set

   !> Unit and default of a keyword of the command (or SET keywords) registered
   !> last; `keyword` may name several (blank-separated) that share them, ''
   !> is the positional arguments.
   subroutine registry_note(this, keyword, unit, default, args)
      class(registry_t), intent(inout) :: this
      character(len=*), intent(in) :: keyword
      character(len=*), intent(in), optional :: unit, default, args
      type(keyword_note_t) :: note
      character(len=:), allocatable :: rest
      integer :: blank
      rest = trim(adjustl(keyword))
      do
         blank = index(rest, ' ')
         if (blank == 0) blank = len(rest) + 1
         note%keyword = to_upper(rest(1:blank - 1))
         note%unit = ''
         note%default = ''
         note%args = ''
         if (present(unit)) note%unit = unit
         if (present(default)) note%default = default
         if (present(args)) note%args = args
         if (this%last_was_set) then
            this%set_notes = [this%set_notes, note]
         else
            associate (e => this%entries(this%n))
               e%notes = [e%notes, note]
               e%nnotes = e%nnotes + 1
            end associate
         end if
         if (blank > len(rest)) exit
         rest = adjustl(rest(blank + 1:))
      end do
   end subroutine registry_note

   !> Index of the command whose canonical (upper-case) name is `name`, 0 if none.
   integer function registry_find(this, name) result(k)
      class(registry_t), intent(in) :: this
      character(len=*), intent(in) :: name
      do k = 1, this%n
         if (to_upper(this%entries(k)%name) == to_upper(name)) return
      end do
      k = 0
   end function registry_find

   !> A handler is registered for the command (else "not yet implemented").
   pure logical function implemented(e)
      type(command_entry_t), intent(in) :: e
      implemented = associated(e%handler)
   end function implemented

   !> Called by a handler that has no error to report (and, with `parsed`, by
   !> one whose command takes no arguments): every handler has the one
   !> interface, `error` and `parsed` included.
   pure subroutine cannot_fail(error, parsed)
      type(error_t), allocatable, intent(inout) :: error
      type(parsed_t), intent(in), optional :: parsed
      if (allocated(error)) deallocate (error)
      if (present(parsed)) return
   end subroutine cannot_fail

   !> The error of a command that needs blocks when no BLOCK has been given.
   subroutine require_block(model, command, error)
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: command
      type(error_t), allocatable, intent(out) :: error
      if (.not. model%geometry%block_created) &
         call set_error(error, command//': no BLOCK has been created')
   end subroutine require_block

   !> FIX and GENERATE: `n` zoned blocks are left (or set) free, with the way
   !> to hold them; `what` says which, after the count.
   subroutine warn_fdef_free(out, command, n, what)
      type(output_t), intent(in) :: out
      character(len=*), intent(in) :: command, what
      integer(ip), intent(in) :: n
      character(len=300) :: text
      write (text, '(a,i0,a)') 'Warning: '//command//': ', n, what//': FDEF blocks cannot be ' &
         //'fixed (manual Section 4.5, FIX); hold their gridpoints with BOUNDARY XVEL 0 YVEL 0'
      call out%line(trim(text))
   end subroutine warn_fdef_free

   !> Push a file source. `defaults` marks the start-up file UDEC.INI (errors
   !> there do not stop a run).
   subroutine context_push_file(ctx, given, error, defaults)
      type(context_t), intent(inout) :: ctx
      character(len=*), intent(in) :: given
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: defaults
      integer :: k
      logical :: ok
      character(len=:), allocatable :: name
      name = context_read_name(ctx, trim(merge('CALL', '    ', ctx%depth > 0)), given)
      do k = 1, ctx%depth
         if (ctx%sources(k)%name == name) then
            call set_error(error, "CALL: file '"//name// &
                           "' is already being read (recursive CALL)")
            return
         end if
      end do
      if (ctx%depth >= max_call_depth) then
         call set_error(error, "CALL: too many nested files (at most 8 sources), cannot read '" &
                        //name//"'")
         return
      end if
      ! a folder or a device (CALL ., CALL /dev/zero) is not a command file
      call check_input_file(trim(merge('CALL', '    ', ctx%depth > 0)), name, error)
      if (allocated(error)) return
      call source_open_file(ctx%sources(ctx%depth + 1), name, ok)
      if (.not. ok) then
         call set_error(error, "cannot open file '"//name//"'")
         return
      end if
      ctx%sources(ctx%depth + 1)%echo = .not. ctx%check_only
      if (present(defaults)) ctx%sources(ctx%depth + 1)%defaults = defaults
      ctx%depth = ctx%depth + 1
   end subroutine context_push_file

   !> The file a reading command (CALL, RESTART) reads for the name the user
   !> gave: that file, or the one whose name differs only in letter case
   !> (core_files' case_match: DOS decks), said in a note; with several such
   !> files a note lists their number and the name stays as given (its error
   !> follows).
   function context_read_name(ctx, command, given) result(name)
      type(context_t), intent(inout) :: ctx
      character(len=*), intent(in) :: command, given
      character(len=:), allocatable :: name
      integer :: count, k
      character(len=12) :: text
      character(len=:), allocatable :: lead, dos, why
      lead = 'note: '
      if (len_trim(command) > 0) lead = lead//trim(command)//': '
      ! a DOS path (CALL GEOM\TUNNEL.DAT): its folder separator read as '/'
      dos = given
      why = ''
      if (index(given, '\') > 0 .and. file_kind(given) == kind_missing) then
         do k = 1, len(dos)
            if (dos(k:k) == '\') dos(k:k) = '/'
         end do
         why = "the DOS folder separator '\' read as '/'"
         if (file_kind(dos) /= kind_missing) then
            name = dos
            call ctx%out%line(lead//"no file '"//given//"'; reading '"//name//"' ("//why//")")
            return
         end if
         why = why//', '
      end if
      call case_match(dos, name, count)
      if (count == 1) then
         call ctx%out%line(lead//"no file '"//given//"'; reading '"//name// &
                           "' ("//why//"the name differs only in letter case)")
      else if (count == 0 .and. len(why) > 0) then
         name = given
      else if (count > 1) then
         write (text, '(i0)') count
         call ctx%out%line(lead//"no file '"//given//"'; "//trim(text)// &
                           ' files differ from it only in letter case: give the exact name')
      end if
   end function context_read_name

   subroutine context_pop_source(ctx)
      type(context_t), intent(inout) :: ctx
      call source_close(ctx%sources(ctx%depth))
      ctx%depth = ctx%depth - 1
   end subroutine context_pop_source

end module commands_context
