!> The command language of UDEC: one table per command, holding its positional
!> arguments, its keywords with their minimum abbreviations and the arguments each
!> keyword takes. Each family module registers its commands' definitions in the
!> manual's own notation (commands_context, commands_catalog; the list with units
!> and defaults is docs/commands.md): the capitalised prefix of a name is the
!> minimum abbreviation (`PROperty` accepts PRO, PROP, PROPERTY). Sources: manual
!> Sections 4.5, 4.6 and 7.4.
!>
!> Argument specification letters:
!>   r real           n real >= 0        p real > 0
!>   i integer        c integer >= 0     q integer >= 1
!>   s file name (raw text up to the next blank)
!>   a any single token (a word, or a number kept as text)
!>   R range: `xl xu yl yu`, `REG x1 y1 .. x4 y4` or `ANN xc yc r1 r2`
!>   [..] optional group, taken when the next token can start it
!>   *  after an item or group: repeat while the next token can start it
!> A definition line is  NAME | positional spec | loose spec | keyword spec; ...
!> where the loose spec applies to numbers that appear where a keyword is
!> expected (the corner list of BLOCK, the pairs of TABLE).
!>
!> Deviations from the manual, needed because the manual's own abbreviations
!> collide: DUmp (D is DAMPING), LInk/LOad (both L), TAble/THERMal/TUnnel (all T),
!> FRAction/FREe. Where the manual gives two keywords of one table the same
!> abbreviation (PLOT Cable/Contacts, History/Hoek, Vel/Vflow; PRINT File/Flows;
!> PRINT BOUNDARY Fluid/Forces) the short form is refused as ambiguous, naming the
!> candidates.
!>
!> Sub-keywords: `Name {A,B,..} spec` lists the keywords of the same command that
!> may follow Name with their own abbreviations (manual casing inside the braces):
!> PRINT CONTACT Disp/Force/State, ZONE STate/STRess, BOUNDARY XHIST Constant ..
!> A token right after such a keyword (or after one of its sub-keywords) is read in
!> that table first (PRINT ZONE ST is ZONE STATE, PRINT CON D is CONTACT DISP),
!> otherwise in the command's own table. PRINT's DISP, FORCES, STATE, FLUID,
!> THERMAL, TEMPERATURE are sub-keywords only in the manual; they stay in the main
!> table (with long minimum abbreviations) so that handlers find them by name.
!>
!> PLOT GRID and LINE take their numbers optionally (GRID alone draws the
!> zones under contours, LINE alone asks for line contours; docs/plot.md).
!>
!> Syntax the manual's own decks use but Section 4 does not document, accepted
!> because it is the program's real language (see examples/application/*/README.md):
!> BOUNDARY LSTRESS (9 values: origin stresses, x- and y-gradients), DELETE with
!> the area as a bare fifth number, FLUID with positional values and DEN=,
!> FFIELD INT, HISTORY SRAT n, PRINT FF, CHANGE ANG, GENERATE AUTO, AZERO < 0,
!> RUN CLOCK t, C for CYCLE and THIS for THIST (Section 7.8 decks), PLOT ABC=n for
!> AB n (the Appendix E decks' history plots).
!>
!> Stricter or wider than the manual (a new user's slips, docs/commands-walk.md):
!> PROPERTY refuses a block keyword (FRIC, D, K, COND ..) after JMAT n, naming the
!> joint keywords meant; MAT n keeps taking joint keywords, as the manual's decks
!> give them. A `;` starts a comment as `*` does (Itasca's later codes; `;` has no
!> other use). The word RANGE, spelt out, may stand before any range (later UDECs
!> write `BOUND YVEL 0 RANGE 0,60 -0.1,0.1`); it is dropped. Ctrl-C / SIGTERM also stop GENERATE, JSET, PLOT and SAVE, which
!> leave the model (and an older save file) as before them.
!>
!> Extensions (commands not in the manual; section 'udec' in the registry and
!> docs/commands.md): HELP; SOLVE <RATIO r> <CYCLES n> (cycle until the force
!> ratio is below r, default 1e-5, at most n cycles, default 100000); EXPORT
!> name.vtu and EXPORT HISTORY name.csv (ParaView and spreadsheet files).
module commands_grammar
   use core_error, only: error_t, set_error
   use core_strings, only: edit_distance
   use commands_tokens, only: to_upper
   implicit none
   private
   public :: grammar_t, command_def_t, keyword_def_t, grammar_build, match_name
   public :: match_none, match_ambiguous, capital_prefix

   integer, parameter :: match_none = 0, match_ambiguous = -1

   type :: keyword_def_t
      character(len=:), allocatable :: name   !< canonical upper-case name
      integer :: min_len = 0                  !< minimum abbreviation length
      character(len=:), allocatable :: spec   !< argument specification
      !> Sub-keywords valid right after this keyword (PRINT CONTACT Disp, BOUNDARY
      !> XHIST Constant): indices of other keywords of the same command and their
      !> minimum abbreviations in this context (manual casing inside {..}).
      integer, allocatable :: sub(:)
      integer, allocatable :: sub_min(:)
   end type keyword_def_t

   type :: command_def_t
      character(len=:), allocatable :: name
      integer :: min_len = 0
      character(len=:), allocatable :: positional
      character(len=:), allocatable :: loose
      integer :: nkeywords = 0
      type(keyword_def_t), allocatable :: keywords(:)
   contains
      procedure :: find_keyword => command_find_keyword
      procedure :: candidates => command_candidates
   end type command_def_t

   type :: grammar_t
      integer :: ncommands = 0
      type(command_def_t), allocatable :: commands(:)
   contains
      procedure :: find_command => grammar_find_command
      procedure :: closest => grammar_closest
      procedure :: command_candidates => grammar_command_candidates
   end type grammar_t

contains

   !> Minimum abbreviation length from manual casing: leading non-lower-case chars.
   pure integer function capital_prefix(name)
      character(len=*), intent(in) :: name
      integer :: i
      capital_prefix = len(name)
      do i = 1, len(name)
         if (name(i:i) >= 'a' .and. name(i:i) <= 'z') then
            capital_prefix = i - 1
            return
         end if
      end do
   end function capital_prefix

   !> Build the grammar from definition lines `NAME|positional|loose|keywords`
   !> (one per command, in the order of the registry: commands_catalog).
   subroutine grammar_build(grammar, defs, error)
      type(grammar_t), intent(out) :: grammar
      character(len=*), intent(in) :: defs(:)
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: line, field(:)
      integer :: i
      allocate (grammar%commands(size(defs)))
      grammar%ncommands = size(defs)
      do i = 1, size(defs)
         line = trim(defs(i))
         call split_fields(line, '|', field)
         if (size(field) /= 4) then
            call set_error(error, 'grammar: malformed definition: '//line)
            return
         end if
         associate (c => grammar%commands(i))
            c%name = to_upper(trim(field(1)))
            c%min_len = capital_prefix(trim(field(1)))
            c%positional = trim(field(2))
            c%loose = trim(field(3))
            call build_keywords(trim(field(4)), c, error)
         end associate
         if (allocated(error)) return
      end do
   end subroutine grammar_build

   subroutine build_keywords(text, command, error)
      character(len=*), intent(in) :: text
      type(command_def_t), intent(inout) :: command
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: entry(:), subs(:), sub_text(:)
      integer :: j, m, blank, open, close
      character(len=:), allocatable :: e, spec
      if (len_trim(text) == 0) then
         allocate (command%keywords(0))
         return
      end if
      call split_fields(text, ';', entry)
      allocate (command%keywords(size(entry)))
      allocate (character(len=len(text)) :: sub_text(size(entry)))
      command%nkeywords = size(entry)
      do j = 1, size(entry)
         e = trim(adjustl(entry(j)))
         blank = index(e, ' ')
         sub_text(j) = ''
         if (blank == 0) then
            command%keywords(j)%name = to_upper(e)
            command%keywords(j)%min_len = capital_prefix(e)
            spec = ''
         else
            command%keywords(j)%name = to_upper(e(1:blank - 1))
            command%keywords(j)%min_len = capital_prefix(e(1:blank - 1))
            spec = trim(adjustl(e(blank + 1:)))
         end if
         ! a leading {A,B,..} lists the sub-keywords of this keyword
         if (len(spec) > 0) then
            if (spec(1:1) == '{') then
               close = index(spec, '}')
               sub_text(j) = spec(2:close - 1)
               spec = trim(adjustl(spec(close + 1:)))
            end if
         end if
         command%keywords(j)%spec = spec
      end do
      do j = 1, size(entry)
         if (len_trim(sub_text(j)) == 0) then
            allocate (command%keywords(j)%sub(0), command%keywords(j)%sub_min(0))
            cycle
         end if
         call split_fields(trim(sub_text(j)), ',', subs)
         allocate (command%keywords(j)%sub(size(subs)), command%keywords(j)%sub_min(size(subs)))
         do m = 1, size(subs)
            e = trim(adjustl(subs(m)))
            command%keywords(j)%sub_min(m) = capital_prefix(e)
            command%keywords(j)%sub(m) = 0
            do open = 1, size(entry)
               if (command%keywords(open)%name == to_upper(e)) command%keywords(j)%sub(m) = open
            end do
            if (command%keywords(j)%sub(m) == 0) then
               call set_error(error, 'grammar: sub-keyword '//e//' of '//command%name//' '// &
                              command%keywords(j)%name//' is not a keyword of '//command%name)
               return
            end if
         end do
      end do
   end subroutine build_keywords

   !> Split `text` at every `sep` (fields padded to a common length).
   subroutine split_fields(text, sep, field)
      character(len=*), intent(in) :: text
      character, intent(in) :: sep
      character(len=:), allocatable, intent(out) :: field(:)
      integer :: n, i, start, k
      n = 1
      do i = 1, len(text)
         if (text(i:i) == sep) n = n + 1
      end do
      allocate (character(len=len(text)) :: field(n))
      start = 1
      k = 0
      do i = 1, len(text) + 1
         if (i > len(text)) then
            k = k + 1
            field(k) = text(start:)
         else if (text(i:i) == sep) then
            k = k + 1
            field(k) = text(start:i - 1)
            start = i + 1
         end if
      end do
   end subroutine split_fields

   !> Does upper-case `token` abbreviate `name` (at least `min_len` chars)?
   pure logical function match_name(token, name, min_len)
      character(len=*), intent(in) :: token, name
      integer, intent(in) :: min_len
      integer :: n
      n = len(token)
      match_name = n >= max(min_len, 1) .and. n <= len(name)
      if (match_name) match_name = name(1:n) == token
   end function match_name

   !> Resolve a token among candidates: an exact full name wins; otherwise the
   !> candidate with the longest minimum abbreviation (the most specific) wins;
   !> a tie is ambiguous.
   subroutine resolve(token, names, min_lens, n, found, prefixes)
      character(len=*), intent(in) :: token
      type(keyword_def_t), intent(in) :: names(:)
      integer, intent(in) :: min_lens(:), n
      integer, intent(out) :: found
      !> a token below every abbreviation that begins two names is ambiguous
      !> (not for a sub-keyword table, whose misses fall back to the command's)
      logical, intent(in), optional :: prefixes
      integer :: i, best_len
      logical :: tie
      found = match_none
      best_len = -1
      tie = .false.
      do i = 1, n
         if (names(i)%name == token) then
            found = i
            return
         end if
      end do
      do i = 1, n
         if (.not. match_name(token, names(i)%name, min_lens(i))) cycle
         if (min_lens(i) > best_len) then
            best_len = min_lens(i)
            found = i
            tie = .false.
         else if (min_lens(i) == best_len) then
            tie = .true.
         end if
      end do
      if (tie) found = match_ambiguous
      ! a token shorter than every minimum abbreviation it begins (BLOCK C:
      ! COnstitutive, CIrcular) names no keyword, but two or more share it:
      ! ambiguous, not unknown
      if (found == match_none .and. present(prefixes)) then
         if (prefixes .and. count([(is_prefix(token, names(i)%name), i=1, n)]) >= 2) found = match_ambiguous
      end if
   end subroutine resolve

   pure logical function is_prefix(token, name)
      character(len=*), intent(in) :: token, name
      is_prefix = len(token) >= 1 .and. len(token) <= len(name)
      if (is_prefix) is_prefix = name(1:len(token)) == token
   end function is_prefix

   !> The names tied for `token` when resolve() finds it ambiguous ("A, B").
   function tied_names(token, names, min_lens, n) result(text)
      character(len=*), intent(in) :: token
      type(keyword_def_t), intent(in) :: names(:)
      integer, intent(in) :: min_lens(:), n
      character(len=:), allocatable :: text
      integer :: i, best_len
      best_len = -1
      do i = 1, n
         if (match_name(token, names(i)%name, min_lens(i))) best_len = max(best_len, min_lens(i))
      end do
      text = ''
      do i = 1, n
         if (best_len < 0) then
            ! no abbreviation reached: the names the token begins (resolve)
            if (.not. is_prefix(token, names(i)%name)) cycle
            if (len(text) > 0) text = text//', '
            text = text//names(i)%name
            cycle
         end if
         if (.not. match_name(token, names(i)%name, min_lens(i))) cycle
         if (min_lens(i) /= best_len) cycle
         if (len(text) > 0) text = text//', '
         text = text//names(i)%name
      end do
   end function tied_names

   subroutine command_table(this, names, lens)
      class(grammar_t), intent(in) :: this
      type(keyword_def_t), allocatable, intent(out) :: names(:)
      integer, allocatable, intent(out) :: lens(:)
      integer :: i
      allocate (names(this%ncommands), lens(this%ncommands))
      do i = 1, this%ncommands
         names(i)%name = this%commands(i)%name
         lens(i) = this%commands(i)%min_len
      end do
   end subroutine command_table

   !> Index of the command `token` names, match_none or match_ambiguous.
   integer function grammar_find_command(this, token) result(found)
      class(grammar_t), intent(in) :: this
      character(len=*), intent(in) :: token
      type(keyword_def_t), allocatable :: names(:)
      integer, allocatable :: lens(:)
      call command_table(this, names, lens)
      call resolve(to_upper(token), names, lens, this%ncommands, found, .true.)
   end function grammar_find_command

   !> The commands an ambiguous `token` could name.
   function grammar_command_candidates(this, token) result(text)
      class(grammar_t), intent(in) :: this
      character(len=*), intent(in) :: token
      character(len=:), allocatable :: text
      type(keyword_def_t), allocatable :: names(:)
      integer, allocatable :: lens(:)
      call command_table(this, names, lens)
      text = tied_names(to_upper(token), names, lens, this%ncommands)
   end function grammar_command_candidates

   !> The keyword table to search: the whole command, or (context > 0) the
   !> sub-keywords of keyword `context`, with their in-context abbreviations.
   subroutine keyword_table(this, context, names, lens, index)
      class(command_def_t), intent(in) :: this
      integer, intent(in) :: context
      type(keyword_def_t), allocatable, intent(out) :: names(:)
      integer, allocatable, intent(out) :: lens(:), index(:)
      integer :: i
      if (context > 0) then
         associate (sub => this%keywords(context)%sub)
            allocate (names(size(sub)), lens(size(sub)), index(size(sub)))
            do i = 1, size(sub)
               names(i)%name = this%keywords(sub(i))%name
               lens(i) = this%keywords(context)%sub_min(i)
               index(i) = sub(i)
            end do
         end associate
      else
         allocate (names(this%nkeywords), lens(this%nkeywords), index(this%nkeywords))
         do i = 1, this%nkeywords
            names(i)%name = this%keywords(i)%name
            lens(i) = this%keywords(i)%min_len
            index(i) = i
         end do
      end if
   end subroutine keyword_table

   !> Index of the keyword `token` names in this command's table (or, with
   !> `context`, among the sub-keywords of keyword `context`).
   integer function command_find_keyword(this, token, context) result(found)
      class(command_def_t), intent(in) :: this
      character(len=*), intent(in) :: token
      integer, intent(in), optional :: context
      type(keyword_def_t), allocatable :: names(:)
      integer, allocatable :: lens(:), index(:)
      integer :: ctx
      found = match_none
      ctx = 0
      if (present(context)) ctx = context
      if (ctx == 0 .and. this%nkeywords == 0) return
      call keyword_table(this, ctx, names, lens, index)
      if (size(names) == 0) return
      call resolve(to_upper(token), names, lens, size(names), found, ctx == 0)
      if (found > 0) found = index(found)
   end function command_find_keyword

   !> The keywords an ambiguous `token` could name (same context rules).
   function command_candidates(this, token, context) result(text)
      class(command_def_t), intent(in) :: this
      character(len=*), intent(in) :: token
      integer, intent(in), optional :: context
      character(len=:), allocatable :: text
      type(keyword_def_t), allocatable :: names(:)
      integer, allocatable :: lens(:), index(:)
      integer :: ctx
      ctx = 0
      if (present(context)) ctx = context
      call keyword_table(this, ctx, names, lens, index)
      text = tied_names(to_upper(token), names, lens, size(names))
   end function command_candidates

   !> Up to three command names closest to `token` (edit distance on the prefix).
   function grammar_closest(this, token) result(text)
      class(grammar_t), intent(in) :: this
      character(len=*), intent(in) :: token
      character(len=:), allocatable :: text
      integer, allocatable :: score(:)
      integer :: i, k, best
      character(len=:), allocatable :: up
      up = to_upper(token)
      allocate (score(this%ncommands))
      do i = 1, this%ncommands
         associate (name => this%commands(i)%name)
            score(i) = edit_distance(up, name(1:min(len(name), max(len(up), &
                                     this%commands(i)%min_len))))
            if (name(1:1) /= up(1:1)) score(i) = score(i) + 1
         end associate
      end do
      text = ''
      do k = 1, 3
         best = minloc(score, 1)
         if (score(best) > max(2, len(up)/2 + 1)) exit
         if (len(text) > 0) text = text//', '
         text = text//this%commands(best)%name
         score(best) = huge(1)
      end do
   end function grammar_closest

end module commands_grammar
