!> The command reference, rendered from the registry: the HELP command's
!> pages and docs/commands.md (`udec --commands-md`) come from the same table
!> the parser reads, so they cannot disagree with it.
module commands_help
   use core_output, only: output_t
   use core_version, only: udec_version, udec_license
   use commands_tokens, only: to_upper, to_lower, substituted
   use commands_grammar, only: grammar_t, command_def_t, match_ambiguous
   use commands_context, only: registry_t, command_entry_t, implemented
   use commands_parser, only: describe, argument_letters
   implicit none
   private
   public :: help_list, help_command, help_markdown, help_man, spec_text, usage_text, argument_name

contains

   !> An argument specification in words-light form: `rrq[r]` -> `r r q [r]`.
   pure function spec_text(spec) result(text)
      character(len=*), intent(in) :: spec
      character(len=:), allocatable :: text
      integer :: i
      text = spec(1:min(1, len(spec)))
      do i = 2, len(spec)
         ! a blank before each letter or bracket, none after `[` nor before `]` or `*`
         if (index(']*', spec(i:i)) == 0 .and. spec(i - 1:i - 1) /= '[') text = text//' '
         text = text//spec(i:i)
      end do
   end function spec_text

   !> The shortest accepted form of a name in manual casing (`PROperty` -> PRO).
   pure function shortest(name, min_len) result(text)
      character(len=*), intent(in) :: name
      integer, intent(in) :: min_len
      character(len=:), allocatable :: text
      text = to_upper(name(1:max(1, min_len)))
   end function shortest

   !> One line of syntax: `JSET r r r r r r r r [r r [r]]`, `PROPERTY keyword ..`.
   function syntax_line(c) result(text)
      type(command_def_t), intent(in) :: c
      character(len=:), allocatable :: text
      text = c%name
      if (len(c%positional) > 0) text = text//' '//spec_text(c%positional)
      if (len(c%loose) > 0) text = text//' ['//spec_text(c%loose)//' ..]'
      if (c%nkeywords > 0) text = text//' keyword ..'
   end function syntax_line

   !> What a parse error that ran out of arguments adds: the syntax line and
   !> the summary, which names the arguments (`TUNNEL r r r q: cut a circular
   !> opening: centre, radius, number of sides`).
   !> When the arguments that ran out are a keyword's (`PLOT JOINT`), its
   !> own syntax is shown: `usage: PLOT JOINT r r r r a [p]`.
   function usage_text(registry, grammar, k, keyword) result(text)
      type(registry_t), intent(in) :: registry
      type(grammar_t), intent(in) :: grammar
      integer, intent(in) :: k
      character(len=*), intent(in), optional :: keyword
      character(len=:), allocatable :: text
      integer :: j
      associate (c => grammar%commands(k))
         if (present(keyword)) then
            do j = 1, c%nkeywords
               if (c%keywords(j)%name /= keyword) cycle
               text = 'usage: '//c%name//' '//c%keywords(j)%name
               if (len(c%keywords(j)%spec) > 0) text = text//' '//spec_text(c%keywords(j)%spec)
               text = text//'; HELP '//c%name//' tells more'
               return
            end do
         end if
         text = 'usage: '//syntax_line(c)
         if (len(argument_names(registry%entries(k))) > 0) &
            text = text//', i.e. '//c%name//' '//argument_names(registry%entries(k))
         text = text//' ('//registry%entries(k)%summary//'); HELP '//c%name//' tells more'
      end associate
   end function usage_text

   !> The positional arguments' names as the manual prints them ('' none).
   function argument_names(e) result(text)
      type(command_entry_t), intent(in) :: e
      character(len=:), allocatable :: text
      integer :: j
      text = ''
      do j = 1, e%nnotes
         if (len(e%notes(j)%keyword) == 0 .and. allocated(e%notes(j)%args)) text = e%notes(j)%args
      end do
   end function argument_names

   !> The name of positional argument `i` (1-based, counting numbers) in the
   !> manual's words, '' when the command names none or has fewer. With
   !> `after_range` (a command whose arguments start with a range, which the
   !> parser reads apart: LOAD R r r) the range's xl xu yl yu are not counted.
   function argument_name(e, i, after_range) result(word)
      type(command_entry_t), intent(in) :: e
      integer, intent(in) :: i
      logical, intent(in) :: after_range
      character(len=:), allocatable :: word, rest
      integer :: n, blank
      rest = argument_names(e)
      word = ''
      n = 0
      do while (len_trim(rest) > 0)
         rest = adjustl(rest)
         blank = index(rest, ' ')
         if (blank == 0) blank = len(rest) + 1
         word = rest(1:blank - 1)
         rest = rest(blank:)
         ! '[', ']' mark optional arguments, not names
         do while (index(word, '[') > 0)
            word = word(:index(word, '[') - 1)//word(index(word, '[') + 1:)
         end do
         do while (index(word, ']') > 0)
            word = word(:index(word, ']') - 1)//word(index(word, ']') + 1:)
         end do
         if (len(word) == 0) cycle
         ! a range's words: the parser reads the range apart (LOAD R r r)
         if (after_range .and. (word == 'xl' .or. word == 'xu' .or. word == 'yl' .or. &
                                word == 'yu')) cycle
         n = n + 1
         if (n == i) return
      end do
      word = ''
   end function argument_name

   !> Unit and default noted for `keyword` of `e` ('' for the positional arguments).
   subroutine note_of(e, keyword, unit, default)
      type(command_entry_t), intent(in) :: e
      character(len=*), intent(in) :: keyword
      character(len=:), allocatable, intent(out) :: unit, default
      integer :: j
      unit = ''
      default = ''
      do j = 1, e%nnotes
         if (e%notes(j)%keyword /= keyword) cycle
         unit = e%notes(j)%unit
         default = e%notes(j)%default
      end do
   end subroutine note_of

   !> The unit and default noted for the positional arguments of `e` as a
   !> sentence, "Arguments in m. Default: 0." ('' when none is noted).
   function arguments_note(e) result(text)
      type(command_entry_t), intent(in) :: e
      character(len=:), allocatable :: text, unit, default
      call note_of(e, '', unit, default)
      text = ''
      if (len(unit) > 0) text = 'Arguments in '//unit//'.'
      if (len(default) > 0) text = trim(adjustl(text//' Default: '//default//'.'))
   end function arguments_note

   !> The keywords whose own minimum abbreviation is refused as ambiguous
   !> (the manual gives two of them one letter): "C could be CABLE, CONTACTS".
   function ambiguity(c, k) result(text)
      type(command_def_t), intent(in) :: c
      integer, intent(in) :: k
      character(len=:), allocatable :: text
      character(len=:), allocatable :: abbrev
      abbrev = shortest(c%keywords(k)%name, c%keywords(k)%min_len)
      text = ''
      if (c%find_keyword(abbrev) == match_ambiguous) &
         text = abbrev//' alone is refused: it could be '//c%candidates(abbrev)
   end function ambiguity

   !> HELP: every command, its shortest form, manual section and summary.
   subroutine help_list(registry, grammar, out)
      type(registry_t), intent(in) :: registry
      type(grammar_t), intent(in) :: grammar
      type(output_t), intent(inout) :: out
      character(len=200) :: line
      integer :: i
      call out%line('Commands (shortest form, manual section); HELP <command> for one:')
      do i = 1, registry%n
         associate (e => registry%entries(i), c => grammar%commands(i))
            write (line, '(2x,a10,1x,a6,1x,a6,1x,a)') c%name, shortest(c%name, c%min_len), &
               e%section, e%summary
            call out%line(trim(line))
         end associate
      end do
   end subroutine help_list

   !> HELP <command>: syntax, keywords with their shortest forms, arguments,
   !> units and defaults, the manual section and the summary.
   subroutine help_command(registry, grammar, k, out)
      type(registry_t), intent(in) :: registry
      type(grammar_t), intent(in) :: grammar
      integer, intent(in) :: k
      type(output_t), intent(inout) :: out
      character(len=:), allocatable :: unit, default, text
      integer :: j
      associate (e => registry%entries(k), c => grammar%commands(k))
         call out%line(c%name//' (shortest form '//shortest(c%name, c%min_len)//', '// &
                       section_text(e%section)//'): '//e%summary)
         call out%line('  syntax: '//syntax_line(c))
         if (len(argument_names(e)) > 0) &
            call out%line('  as the manual writes it: '//c%name//' '//argument_names(e))
         text = letters_used(c)
         if (len(text) > 0) call out%line('  where '//text)
         call note_of(e, '', unit, default)
         if (len(unit) > 0) call out%line('  arguments in '//unit)
         if (len(default) > 0) call out%line('  default: '//default)
         if (.not. implemented(e)) &
            call out%line('  (parsed and checked; not yet implemented)')
         if (c%nkeywords == 0) return
         call out%line('  keywords (shortest form, arguments, unit, default):')
         do j = 1, c%nkeywords
            call out%line('    '//keyword_text(e, c, j))
         end do
      end associate
   end subroutine help_command

   !> The argument letters a command's syntax uses, in words, so that HELP
   !> CYCLE reads `syntax: CYCLE c` / `where c: an integer >= 0`.
   function letters_used(c) result(text)
      type(command_def_t), intent(in) :: c
      character(len=:), allocatable :: text, specs
      integer :: j
      specs = c%positional//c%loose
      do j = 1, c%nkeywords
         specs = specs//c%keywords(j)%spec
      end do
      text = letters_in_words(specs, '')
   end function letters_used

   !> The argument letters that occur in `specs`, in words, each letter
   !> between `quote`s: "r: a real number; c: an integer >= 0" (HELP's
   !> "where" line; with every letter, the legend of docs/commands.md and
   !> udec.1).
   function letters_in_words(specs, quote) result(text)
      character(len=*), intent(in) :: specs, quote
      character(len=:), allocatable :: text
      character :: letter
      integer :: i
      text = ''
      do i = 1, len(argument_letters)
         letter = argument_letters(i:i)
         if (index(specs, letter) == 0) cycle
         if (len(text) > 0) text = text//'; '
         text = text//quote//letter//quote//': '//describe(letter)
      end do
   end function letters_in_words

   !> One keyword j of command c in words: its name and shortest form, its
   !> arguments, unit and default, the sub-keywords that may follow it and
   !> the refusal of an ambiguous shortest form (HELP <command>, udec.1).
   function keyword_text(e, c, j) result(text)
      type(command_entry_t), intent(in) :: e
      type(command_def_t), intent(in) :: c
      integer, intent(in) :: j
      character(len=:), allocatable :: text, unit, default
      associate (kw => c%keywords(j))
         call note_of(e, kw%name, unit, default)
         text = kw%name//' ('//shortest(kw%name, kw%min_len)//')'
         if (len(kw%spec) > 0) text = text//' '//spec_text(kw%spec)
         if (len(unit) > 0) text = text//' ['//unit//']'
         if (len(default) > 0) text = text//' default '//default
         if (size(kw%sub) > 0) text = text//' then '//sub_list(c, j)
         if (len(ambiguity(c, j)) > 0) text = text//'; '//ambiguity(c, j)
      end associate
   end function keyword_text

   !> The sub-keywords of keyword j with their in-context shortest forms.
   function sub_list(c, j) result(text)
      type(command_def_t), intent(in) :: c
      integer, intent(in) :: j
      character(len=:), allocatable :: text
      integer :: m
      text = ''
      associate (kw => c%keywords(j))
         do m = 1, size(kw%sub)
            if (m > 1) text = text//', '
            text = text//c%keywords(kw%sub(m))%name//' ('// &
                   shortest(c%keywords(kw%sub(m))%name, kw%sub_min(m))//')'
         end do
      end associate
   end function sub_list

   !> docs/commands.md, one line per record, written to `unit`.
   subroutine help_markdown(registry, grammar, unit)
      type(registry_t), intent(in) :: registry
      type(grammar_t), intent(in) :: grammar
      integer, intent(in) :: unit
      character(len=:), allocatable :: unit_text, default, text
      integer :: i, j
      write (unit, '(a)') '# Command reference', '', &
         'Generated by `udec --commands-md` from the command registry (each family module in', &
         '`src/commands/` registers its commands); do not edit by hand. The test', &
         '`unit.commands_md_current` fails when this file differs from what the program prints.', &
         '', &
         'Argument letters: '//letters_in_words(argument_letters, '`')//'.', &
         '`[..]` optional, `*` repeated. A command', &
         'whose syntax is `[R]` takes its range before its keywords, as in the manual, or after', &
         'them (`BOUND STRESS 0 0 -1e6 0,10 9.9,10.1`). A name is', &
         'accepted from its shortest form up to its full spelling. Where the manual gives two', &
         'keywords one shortest form, that form is refused as ambiguous and the message names', &
         'the candidates. `HELP` and `HELP <command>` print the same information in the program.', &
         ''
      write (unit, '(a)') '| command | shortest | section | summary |', '|---|---|---|---|'
      do i = 1, registry%n
         associate (e => registry%entries(i), c => grammar%commands(i))
            write (unit, '(a)') '| ['//c%name//'](#'//to_lower(c%name)//') | '// &
               shortest(c%name, c%min_len)//' | '//e%section//' | '//e%summary//' |'
         end associate
      end do
      do i = 1, registry%n
         associate (e => registry%entries(i), c => grammar%commands(i))
            write (unit, '(a)') '', '## '//c%name, ''
            write (unit, '(a)') e%summary//'. '//capitalised(section_text(e%section))// &
               '; shortest form `'// &
               shortest(c%name, c%min_len)//'`; registered by `commands_'//e%family//'`.'
            if (.not. implemented(e)) &
               write (unit, '(a)') '', 'Parsed and checked (`udec --check`), not yet implemented.'
            write (unit, '(a)') '', '    '//syntax_line(c)
            if (len(argument_names(e)) > 0) &
               write (unit, '(a)') '', 'As the manual writes it: `'//c%name//' '//argument_names(e)//'`.'
            text = arguments_note(e)
            if (len(text) > 0) write (unit, '(a)') '', text
            if (c%nkeywords == 0) cycle
            write (unit, '(a)') '', '| keyword | shortest | arguments | unit | default | notes |', &
               '|---|---|---|---|---|---|'
            do j = 1, c%nkeywords
               associate (kw => c%keywords(j))
                  call note_of(e, kw%name, unit_text, default)
                  text = ''
                  if (size(kw%sub) > 0) text = 'then '//sub_list(c, j)
                  if (len(ambiguity(c, j)) > 0) then
                     if (len(text) > 0) text = text//'; '
                     text = text//ambiguity(c, j)
                  end if
                  write (unit, '(a)') '| '//kw%name//' | '//shortest(kw%name, kw%min_len)// &
                     ' | '//spec_text(kw%spec)//' | '//unit_text//' | '//default//' | '// &
                     text//' |'
               end associate
            end do
         end associate
      end do
   end subroutine help_markdown

   !> The manual page udec.1 (`udec --man`), in man(7) roff: the options of
   !> the program, then every command of the registry with its syntax,
   !> section, summary and keywords (shortest form, arguments, unit, default).
   subroutine help_man(registry, grammar, unit)
      type(registry_t), intent(in) :: registry
      type(grammar_t), intent(in) :: grammar
      integer, intent(in) :: unit
      character(len=:), allocatable :: text
      integer :: i, j
      write (unit, '(a)') &
         '.\" Generated by `udec --man` from the command registry; do not edit by hand.', &
         '.TH UDEC 1 "" "udec '//udec_version//'" "User Commands"', &
         '.SH NAME', &
         'udec \- two-dimensional distinct element program for jointed rock', &
         '.SH SYNOPSIS', &
         '.B udec', '.RI [ FILE ]', '.br', &
         '.B udec \-\-check', '.IR FILE ...', '.br', &
         '.B udec', '.RB [ \-\-commands\-md | \-\-man | \-\-help | \-\-version ]', &
         '.SH DESCRIPTION', &
         'udec reimplements UDEC, the distinct element code for jointed rock masses,', &
         'and reads the command language of its 1989 manual (version ICG1.5).', &
         'Without', '.I FILE', 'it runs', '.B DATA', &
         'in batch mode when that file exists, otherwise it starts the interactive', &
         '.B UDEC>', 'prompt. In batch mode the output goes to the screen and to the file', &
         '.BR OUT .', &
         '.B UDEC.INI', 'in the working folder is read first when present.', &
         '.PP', &
         'Only the capitalised prefix of a command or keyword must be typed; delimiters', &
         'are blanks and ( ) , / =; * starts a comment; & ends a line that continues.', &
         '.SH OPTIONS', &
         '.TP', '.BI \-\-check " FILE..."', 'parse the files only and report every syntax error', &
         '.TP', '.B \-\-commands\-md', 'print the command reference (docs/commands.md) and stop', &
         '.TP', '.B \-\-man', 'print this manual page and stop', &
         '.TP', '.BR \-h ", " \-\-help', 'show the usage', &
         '.TP', '.BR \-V ", " \-\-version', 'show the version, the licence and the linked libraries', &
         '.SH COMMANDS', &
         roff('Argument letters: '//letters_in_words(argument_letters, '')//'.'), &
         '[..] optional, * repeated. A command whose syntax is [R]', &
         'takes its range before its keywords, as in the manual, or after them.', &
         'Sections are those of the UDEC manual (ICG1.5, 1989); "udec" marks a command', &
         'that is not in the manual (an extension).'
      do i = 1, registry%n
         associate (e => registry%entries(i), c => grammar%commands(i))
            write (unit, '(a)') '.TP', '.B '//roff(syntax_line(c)), &
               roff(capitalised(e%summary))//' ('//roff(section_text(e%section))// &
               '; shortest form '//shortest(c%name, c%min_len)//').'
            if (.not. implemented(e)) &
               write (unit, '(a)') 'Parsed and checked, not yet implemented.'
            if (len(argument_names(e)) > 0) &
               write (unit, '(a)') 'As the manual writes it: '//roff(c%name//' '//argument_names(e))//'.'
            text = arguments_note(e)
            if (len(text) > 0) write (unit, '(a)') roff(text)
            if (c%nkeywords == 0) cycle
            write (unit, '(a)') '.RS', 'Keywords:'
            do j = 1, c%nkeywords
               write (unit, '(a)') '.br', roff(keyword_text(e, c, j))
            end do
            write (unit, '(a)') '.RE'
         end associate
      end do
      write (unit, '(a)') '.SH FILES', &
         '.TP', '.B DATA', 'the batch deck read when no FILE is given', &
         '.TP', '.B UDEC.INI', 'commands read before the deck or the prompt', &
         '.TP', '.B OUT', 'the batch output', &
         '.SH EXIT STATUS', &
         '0 after STOP or the end of the input; 1 after an input error in batch mode', &
         '(or any error with \-\-check); 2 for bad command\-line usage; 128 + signal', &
         'after SIGINT or SIGTERM in a batch run. Ctrl\-C stops a running CYCLE, SOLVE,', &
         'STEP or RUN at the end of a step; twice within 2 s it quits.', &
         '.SH SEE ALSO', &
         'The command reference docs/commands.md (installed under share/doc/udec).', &
         '.SH LICENSE', &
         udec_license//' (the file LICENSE); copyright the udec authors.'
   end subroutine help_man

   !> Text for a roff line: backslashes escaped, minus signs as \-, a
   !> leading dot or quote protected.
   pure function roff(text) result(out)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: out
      out = substituted(text, '\-', '\e\-', 2)
      if (len(out) > 0) then
         if (out(1:1) == '.' .or. out(1:1) == "'") out = '\&'//out
      end if
   end function roff

   !> 'manual Section 4.5', or for this program's own commands (section
   !> 'udec') 'not in the manual'.
   pure function section_text(section) result(text)
      character(len=*), intent(in) :: section
      character(len=:), allocatable :: text
      if (section == 'udec') then
         text = 'not in the manual'
      else
         text = 'manual Section '//section
      end if
   end function section_text

   pure function capitalised(text) result(cap)
      character(len=*), intent(in) :: text
      character(len=len(text)) :: cap
      cap = text
      if (len(text) > 0) cap(1:1) = to_upper(text(1:1))
   end function capitalised

end module commands_help
