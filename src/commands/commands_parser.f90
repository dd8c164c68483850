!> Parse one tokenized command line against the grammar tables. The result is a
!> list of items (the positional arguments, then each keyword with its values)
!> that handlers read by canonical keyword name. Parsing never touches the model:
!> a command whose syntax is wrong is rejected before any handler runs.
module commands_parser
   use core_kinds, only: wp
   use core_error, only: error_t, set_error
   use core_strings, only: edit_distance
   use core_range, only: range_t, range_box, range_region, range_annulus
   use commands_tokens, only: token_t, to_upper, printable
   use commands_numbers, only: looks_numeric, parse_real, parse_integer, number_ok, &
                               number_out_of_range, number_not_integer
   use commands_grammar, only: grammar_t, command_def_t, match_name, match_none, &
                               match_ambiguous
   implicit none
   private
   public :: parsed_t, item_t, value_t, parse_command, parse_range_tokens, describe
   public :: argument_letters
   public :: value_real, value_integer, value_text
   public :: item_positional, item_loose

   integer, parameter :: value_real = 1, value_integer = 2, value_text = 3
   integer, parameter :: item_positional = 0, item_loose = -1

   !> The argument letters of a syntax (commands_grammar) in the order HELP
   !> lists them, and what each stands for (`describe`).
   character(len=*), parameter :: argument_letters = 'rnpicqsatR'
   character(len=*), parameter :: argument_words(len(argument_letters)) = [character(len=62) :: &
      'a real number', 'a real number >= 0', 'a real number > 0', 'an integer', &
      'an integer >= 0', 'an integer >= 1', 'a file name', 'a word or number', &
      'the rest of the line, as typed', &
      'a range (xl xu yl yu, REG x1 y1 .. x4 y4 or ANN xc yc r1 r2)']

   type :: value_t
      integer :: kind = value_real
      real(wp) :: r = 0.0_wp
      integer :: i = 0
      character(len=:), allocatable :: text
   end type value_t

   !> One keyword occurrence (or the positional / loose arguments).
   type :: item_t
      integer :: keyword = item_positional    !< index in the command's table
      character(len=:), allocatable :: name   !< canonical keyword name ('' if none)
      integer :: first = 1                    !< first value index
      integer :: count = 0                    !< number of values
      integer :: token = 0                    !< token index where it started
   end type item_t

   type :: parsed_t
      integer :: command = 0
      character(len=:), allocatable :: name       !< canonical command name
      logical :: has_range = .false.
      type(range_t) :: range   !< unset (holds every point) when has_range is false
      integer :: nitems = 0
      type(item_t), allocatable :: items(:)
      integer :: nvalues = 0
      type(value_t), allocatable :: values(:)
   contains
      procedure :: find => parsed_find
      procedure :: count_of => parsed_count_of
      procedure :: real_at => parsed_real_at
      procedure :: int_at => parsed_int_at
      procedure :: text_at => parsed_text_at
      procedure :: beyond => parsed_beyond
      procedure, private :: take_int => parsed_take_int
      procedure, private :: take_real => parsed_take_real
      procedure, private :: take_flag => parsed_take_flag
      generic :: take => take_int, take_real, take_flag
   end type parsed_t

   !> Parsing state for one line: the line, its tokens and the next one.
   type :: cursor_t
      character(len=:), allocatable :: line
      type(token_t), allocatable :: tokens(:)
      integer :: it = 1
      integer :: ntokens = 0
      character(len=:), allocatable :: context
   end type cursor_t

contains

   !> Index of the first item whose keyword is `name` (canonical), 0 if absent.
   integer function parsed_find(this, name) result(k)
      class(parsed_t), intent(in) :: this
      character(len=*), intent(in) :: name
      do k = 1, this%nitems
         if (this%items(k)%keyword > 0) then
            if (this%items(k)%name == name) return
         end if
      end do
      k = 0
   end function parsed_find

   !> How many items of the line are one of the keywords `names` (canonical),
   !> and the index of the last of them (0 if none): for the commands that
   !> take exactly one of several keywords.
   integer function parsed_count_of(this, names, last) result(n)
      class(parsed_t), intent(in) :: this
      character(len=*), intent(in) :: names(:)
      integer, intent(out), optional :: last
      integer :: k
      n = 0
      if (present(last)) last = 0
      do k = 1, this%nitems
         if (.not. any(names == this%items(k)%name)) cycle
         n = n + 1
         if (present(last)) last = k
      end do
   end function parsed_count_of

   !> Value `j` (1-based) of item `k` as a real (integers convert).
   real(wp) function parsed_real_at(this, k, j) result(v)
      class(parsed_t), intent(in) :: this
      integer, intent(in) :: k, j
      associate (val => this%values(this%items(k)%first + j - 1))
         if (val%kind == value_integer) then
            v = real(val%i, wp)
         else
            v = val%r
         end if
      end associate
   end function parsed_real_at

   integer function parsed_int_at(this, k, j) result(v)
      class(parsed_t), intent(in) :: this
      integer, intent(in) :: k, j
      v = this%values(this%items(k)%first + j - 1)%i
   end function parsed_int_at

   !> Index of the first real value of the line whose magnitude is not at
   !> most `limit` (NaN included), 0 if none: the commands whose numbers are
   !> squared (coordinates, stresses) refuse such a number before they act.
   integer function parsed_beyond(this, limit) result(k)
      class(parsed_t), intent(in) :: this
      real(wp), intent(in) :: limit
      do k = 1, this%nvalues
         if (this%values(k)%kind /= value_real) cycle
         if (.not. abs(this%values(k)%r) <= limit) return
      end do
      k = 0
   end function parsed_beyond

   !> When item k is keyword `name`: its (first) value into `var` (SET's
   !> keywords that only store a number, one line each).
   subroutine parsed_take_int(this, k, name, var)
      class(parsed_t), intent(in) :: this
      integer, intent(in) :: k
      character(len=*), intent(in) :: name
      integer, intent(inout) :: var
      if (this%items(k)%name == name) var = this%int_at(k, 1)
   end subroutine parsed_take_int

   subroutine parsed_take_real(this, k, name, var)
      class(parsed_t), intent(in) :: this
      integer, intent(in) :: k
      character(len=*), intent(in) :: name
      real(wp), intent(inout) :: var
      if (this%items(k)%name == name) var = this%real_at(k, 1)
   end subroutine parsed_take_real

   !> A switch: item k is keyword `name` (on) or `-name` (off).
   subroutine parsed_take_flag(this, k, name, var)
      class(parsed_t), intent(in) :: this
      integer, intent(in) :: k
      character(len=*), intent(in) :: name
      logical, intent(inout) :: var
      if (this%items(k)%name == name) var = .true.
      if (this%items(k)%name == '-'//name) var = .false.
   end subroutine parsed_take_flag

   function parsed_text_at(this, k, j) result(v)
      class(parsed_t), intent(in) :: this
      integer, intent(in) :: k, j
      character(len=:), allocatable :: v
      v = this%values(this%items(k)%first + j - 1)%text
   end function parsed_text_at

   !> Parse `tokens(1:ntokens)` of `line`; tokens(1) names the command.
   subroutine parse_command(grammar, line, tokens, ntokens, parsed, error)
      type(grammar_t), intent(in) :: grammar
      character(len=*), intent(in) :: line
      type(token_t), intent(in) :: tokens(:)
      integer, intent(in) :: ntokens
      type(parsed_t), intent(out) :: parsed
      type(error_t), allocatable, intent(out) :: error
      type(cursor_t) :: cur
      integer :: icmd, k, loose_item, ctx
      character(len=:), allocatable :: closest

      ! every item but the positional one starts at a token and every value
      ! takes one token at least, so the lists are never outgrown
      allocate (parsed%items(max(8, ntokens + 1)), parsed%values(max(16, ntokens)))
      icmd = grammar%find_command(tokens(1)%text)
      if (icmd == match_none) then
         closest = grammar%closest(tokens(1)%text)
         if (len(closest) > 0) then
            call set_error(error, "unknown command '"//printable(tokens(1)%text)// &
                           "' (closest known commands: "//closest//")")
         else
            call set_error(error, "unknown command '"//printable(tokens(1)%text)//"'")
         end if
         return
      else if (icmd == match_ambiguous) then
         call set_error(error, "ambiguous command abbreviation '"// &
                        printable(tokens(1)%text)//"' (could be "// &
                        grammar%command_candidates(tokens(1)%text)//"; type more letters)")
         return
      end if
      parsed%command = icmd
      associate (cmd => grammar%commands(icmd))
         parsed%name = cmd%name
         cur%it = 2
         cur%line = line
         cur%tokens = tokens(1:ntokens)
         cur%ntokens = ntokens
         cur%context = cmd%name
         call new_item(parsed, item_positional, '', 1)
         call consume(cmd%positional, cmd, cur, parsed, parsed%nitems, error)
         if (allocated(error)) return
         loose_item = 0
         ctx = 0
         do while (cur%it <= cur%ntokens)
            associate (tok => tokens(cur%it)%text)
               ! a range may follow the keywords too (`BOUND STRESS 0 0 -1e6
               ! 0,10 9.9,10.1`): the manual puts it first, later UDECs last
               if (trailing_range(cmd, tok, parsed)) then
                  cur%context = cmd%name//' (range)'
                  k = cur%it
                  call consume_one('R', cur, parsed, 1, error)
                  if (allocated(error)) then
                     call explain_short_range(cmd%name, parsed, tokens(k:ntokens), error)
                     return
                  end if
                  cycle
               end if
               if (looks_numeric(tok)) then
                  if (len(cmd%loose) == 0) then
                     call set_error(error, cmd%name//": unexpected number '"//printable(tok)// &
                                    "'"//after_keyword(grammar, cmd, parsed, tokens)// &
                                    " (expected "//expected_keyword(cmd)//")")
                     return
                  end if
                  if (loose_item == 0) then
                     call new_item(parsed, item_loose, '', cur%it)
                     loose_item = parsed%nitems
                  end if
                  cur%context = cmd%name
                  call consume(cmd%loose, cmd, cur, parsed, loose_item, error)
                  if (allocated(error)) return
               else
                  ! after a keyword with sub-keywords (PRINT CONTACT Disp Force State),
                  ! the token is first read with the sub-keywords' own abbreviations
                  k = match_none
                  if (ctx > 0) then
                     k = cmd%find_keyword(tok, ctx)
                     if (k == match_ambiguous) then
                        call set_error(error, cmd%name//' '//cmd%keywords(ctx)%name// &
                                       ": ambiguous keyword '"//printable(tok)// &
                                       "' (could be "//cmd%candidates(tok, ctx)// &
                                       "; type more letters)")
                        return
                     end if
                  end if
                  if (k == match_none) then
                     k = cmd%find_keyword(tok)
                     if (k == match_none) then
                        call set_error(error, cmd%name//": unknown keyword '"//printable(tok)// &
                                       "' ("//closest_keywords(cmd, tok)//"expected "// &
                                       expected_keyword(cmd, tok)//")"//elastic_hint(cmd, tok))
                        return
                     else if (k == match_ambiguous) then
                        call set_error(error, cmd%name//": ambiguous keyword '"//printable(tok)// &
                                       "' (could be "//cmd%candidates(tok)// &
                                       "; type more letters)")
                        return
                     end if
                     ctx = 0
                     if (size(cmd%keywords(k)%sub) > 0) ctx = k
                  end if
                  call new_item(parsed, k, cmd%keywords(k)%name, cur%it)
                  cur%it = cur%it + 1
                  cur%context = cmd%name//' '//cmd%keywords(k)%name
                  call consume(cmd%keywords(k)%spec, cmd, cur, parsed, parsed%nitems, error)
                  if (allocated(error)) return
               end if
            end associate
         end do
      end associate
   end subroutine parse_command

   !> A range after the keywords that ran out of numbers is most often a
   !> keyword given too many values (`INSITU STRESS 0 0 0 YGRAD 0 0 0 0 0 0`):
   !> say which numbers were left over and whose values they follow.
   subroutine explain_short_range(name, parsed, rest, error)
      character(len=*), intent(in) :: name
      type(parsed_t), intent(in) :: parsed
      type(token_t), intent(in) :: rest(:)
      type(error_t), allocatable, intent(inout) :: error
      character(len=:), allocatable :: left, after
      integer :: k
      if (index(error%message, '(line ended)') == 0 .or. size(rest) == 0) return
      if (.not. looks_numeric(rest(1)%text)) return
      left = printable(rest(1)%text)
      do k = 2, size(rest)
         left = left//' '//printable(rest(k)%text)
      end do
      after = 'the keywords'
      if (parsed%nitems > 1) then
         if (len(parsed%items(parsed%nitems)%name) > 0) &
            after = parsed%items(parsed%nitems)%name//"'s values"
      end if
      call set_error(error, name//": the numbers left after "//after//" ('"//left// &
                     "') are read as a range xl xu yl yu, which needs 4 numbers (line ended)")
   end subroutine explain_short_range

   !> Is `tok`, met after the keywords, the start of the command's optional
   !> range? Only for commands whose positional part is just `[R]` (or
   !> DELETE's `[R[n]]`: DELETE AREA 0.5 0 10 0 10), when no range was given
   !> before the keywords.
   logical function trailing_range(cmd, tok, parsed)
      type(command_def_t), intent(in) :: cmd
      character(len=*), intent(in) :: tok
      type(parsed_t), intent(in) :: parsed
      trailing_range = .false.
      if ((cmd%positional /= '[R]' .and. cmd%positional /= '[R[n]]') .or. parsed%has_range .or. &
          len(cmd%loose) > 0) return
      if (looks_numeric(tok)) then
         trailing_range = .true.
      else if (is_range_word(tok)) then
         trailing_range = cmd%find_keyword(tok) == match_none
      end if
   end function trailing_range

   !> For "unexpected number": the keyword the numbers follow, as read, when
   !> it takes no more (`BOUND YV 0`: YV is YVISC, which takes none; PLOT
   !> WINDOW 0 5 0 5: PLOT's WINDOW draws the frame, the WINDOW command sets
   !> it), naming the keywords of the same start that do take a value and a
   !> command of that name; '' after the positional arguments.
   function after_keyword(grammar, cmd, parsed, tokens) result(text)
      type(grammar_t), intent(in) :: grammar
      type(command_def_t), intent(in) :: cmd
      type(parsed_t), intent(in) :: parsed
      type(token_t), intent(in) :: tokens(:)
      character(len=:), allocatable :: text, typed, others
      integer :: k, i, c
      text = ''
      k = parsed%items(parsed%nitems)%keyword
      if (k <= 0) return
      associate (name => cmd%keywords(k)%name)
         typed = to_upper(tokens(parsed%items(parsed%nitems)%token)%text)
         text = ' after '//name
         if (typed /= name) text = text//" (read from '"//printable(tokens( &
                                   parsed%items(parsed%nitems)%token)%text)//"')"
         if (len_trim(cmd%keywords(k)%spec) == 0) then
            text = text//', which takes no value'
         else
            text = text//', which takes no more values'
         end if
         others = ''
         do i = 1, cmd%nkeywords
            if (i == k .or. len_trim(cmd%keywords(i)%spec) == 0) cycle
            if (len(cmd%keywords(i)%name) < len(typed)) cycle
            if (cmd%keywords(i)%name(1:len(typed)) /= typed) cycle
            if (len(others) > 0) others = others//', '
            others = others//cmd%keywords(i)%name//' (shortest form '// &
                     cmd%keywords(i)%name(1:max(1, cmd%keywords(i)%min_len))//')'
         end do
         if (len(others) > 0) text = text//'; did you mean '//others//'?'
         c = match_none
         if (len_trim(cmd%keywords(k)%spec) == 0) c = grammar%find_command(name)
         if (c > 0) then
            if (grammar%commands(c)%name == name .and. &
                len_trim(grammar%commands(c)%positional) > 0) &
               text = text//'; '//name//' with numbers is the command '//name// &
                      ', given on a line of its own (HELP '//name//')'
         end if
      end associate
   end function after_keyword

   !> What a keyword position accepts, for messages.
   function expected_keyword(cmd, token) result(text)
      type(command_def_t), intent(in) :: cmd
      character(len=*), intent(in), optional :: token
      character(len=:), allocatable :: text
      integer :: i, shown
      logical :: filtered
      if (cmd%nkeywords == 0) then
         text = 'no further input'
         return
      end if
      ! a long list is cut to the keywords of the token's first letter, and
      ! says so (PROPERTY's 'bogus' read "expected a keyword of PROPERTY: BULK")
      filtered = .false.
      if (present(token)) filtered = len(token) > 0 .and. cmd%nkeywords > 8
      text = 'a keyword of '//cmd%name//': '
      if (filtered) text = 'a keyword of '//cmd%name//' (those starting with '// &
                           to_upper(token(1:1))//': '
      shown = 0
      do i = 1, cmd%nkeywords
         if (filtered) then
            if (cmd%keywords(i)%name(1:1) /= to_upper(token(1:1))) cycle
         end if
         if (shown == 8) then
            text = text//', ...'
            exit
         end if
         if (shown > 0) text = text//', '
         text = text//cmd%keywords(i)%name
         shown = shown + 1
      end do
      if (filtered) text = text//'; HELP '//cmd%name//' lists all)'
      if (shown == 0) text = 'a keyword of '//cmd%name//' (HELP '//cmd%name//' lists them)'
      ! a command that takes a range there (DELETE, FIX, CHANGE, PRINT ..)
      if (allocated(cmd%positional)) then
         if (index(cmd%positional, 'R') > 0) text = text//', or a range (xl xu yl yu, ' // &
                                                     'REG x1 y1 .. x4 y4 or ANN xc yc r1 r2)'
      end if
   end function expected_keyword

   !> PROPERTY E=.. or NU=.. (Young's modulus and Poisson's ratio, as a new
   !> user types them): the manual's PROPERTY takes the bulk and shear moduli
   !> (Section 4.5, PROPERTY note), so say how to get them; '' otherwise.
   function elastic_hint(cmd, token) result(text)
      type(command_def_t), intent(in) :: cmd
      character(len=*), intent(in) :: token
      character(len=:), allocatable :: text
      character(len=:), allocatable :: up
      up = to_upper(token)
      text = ''
      if (cmd%name /= 'PROPERTY') return
      select case (up)
      case ('E', 'EMOD', 'YM', 'YMOD', 'NU', 'V', 'PR')
      case default
         if (index(up, 'YOUNG') /= 1 .and. index(up, 'POISS') /= 1) return
      end select
      text = "; PROPERTY takes the bulk and shear moduli (manual Section 4.5): "// &
             "K = E / (3 (1 - 2 nu)), G = E / (2 (1 + nu))"
   end function elastic_hint

   !> "closest: A, B; " naming up to three keywords of `cmd` within a small
   !> edit distance of `token` (a misspelt PROPERTY name, say), or ''.
   function closest_keywords(cmd, token) result(text)
      type(command_def_t), intent(in) :: cmd
      character(len=*), intent(in) :: token
      character(len=:), allocatable :: text
      integer :: score(cmd%nkeywords), i, k
      character(len=:), allocatable :: up
      up = to_upper(token)
      do i = 1, cmd%nkeywords
         score(i) = edit_distance(up, cmd%keywords(i)%name)
      end do
      text = ''
      do k = 1, min(3, cmd%nkeywords)
         i = minloc(score, 1)
         if (score(i) > max(1, len(up)/3)) exit
         if (len(text) == 0) then
            text = 'closest: '//cmd%keywords(i)%name
         else
            text = text//', '//cmd%keywords(i)%name
         end if
         score(i) = huge(1)
      end do
      if (len(text) > 0) text = text//'; '
   end function closest_keywords

   subroutine new_item(parsed, keyword, name, token)
      type(parsed_t), intent(inout) :: parsed
      integer, intent(in) :: keyword, token
      character(len=*), intent(in) :: name
      parsed%nitems = parsed%nitems + 1
      parsed%items(parsed%nitems)%keyword = keyword
      parsed%items(parsed%nitems)%name = name
      parsed%items(parsed%nitems)%first = parsed%nvalues + 1
      parsed%items(parsed%nitems)%count = 0
      parsed%items(parsed%nitems)%token = token
   end subroutine new_item

   subroutine push_value(parsed, item, value)
      type(parsed_t), intent(inout) :: parsed
      integer, intent(in) :: item
      type(value_t), intent(in) :: value
      parsed%nvalues = parsed%nvalues + 1
      parsed%values(parsed%nvalues) = value
      parsed%items(item)%count = parsed%items(item)%count + 1
   end subroutine push_value

   !> Position of the `]` matching the `[` at `open`.
   pure integer function matching_bracket(spec, open) result(close)
      character(len=*), intent(in) :: spec
      integer, intent(in) :: open
      integer :: depth
      depth = 0
      do close = open, len(spec)
         if (spec(close:close) == '[') depth = depth + 1
         if (spec(close:close) == ']') depth = depth - 1
         if (depth == 0) return
      end do
      close = len(spec)
   end function matching_bracket

   !> First item letter of a spec (skipping brackets).
   pure character function first_letter(spec)
      character(len=*), intent(in) :: spec
      integer :: j
      first_letter = ' '
      do j = 1, len(spec)
         if (spec(j:j) /= '[' .and. spec(j:j) /= ']') then
            first_letter = spec(j:j)
            return
         end if
      end do
   end function first_letter

   !> Can the next token start an item of kind `c`?
   logical function can_start(c, cmd, cur)
      character, intent(in) :: c
      type(command_def_t), intent(in) :: cmd
      type(cursor_t), intent(in) :: cur
      can_start = .false.
      if (cur%it > cur%ntokens) return
      associate (tok => cur%tokens(cur%it)%text)
         select case (c)
         case ('r', 'n', 'p', 'i', 'c', 'q')
            can_start = looks_numeric(tok)
         case ('R')
            can_start = looks_numeric(tok) .or. is_range_word(tok)
         case ('s', 'a')
            can_start = looks_numeric(tok) .or. cmd%find_keyword(tok) == match_none
         case ('t')
            can_start = .true.
         end select
      end associate
   end function can_start

   !> REG / ANN start a range; so does the word RANGE, spelt out (not
   !> abbreviated: RA is SOLVE's RATIO), which the manual does not have but
   !> later UDEC versions put before every range (`BOUND YVEL 0 RANGE 0,60
   !> -0.1,0.1`): an extension, read as a range with the word dropped.
   logical function is_range_word(tok)
      character(len=*), intent(in) :: tok
      is_range_word = match_name(to_upper(tok), 'REGION', 3) .or. &
                      match_name(to_upper(tok), 'ANNULUS', 3) .or. to_upper(tok) == 'RANGE'
   end function is_range_word

   !> Consume tokens according to `spec`, appending values to item `item`.
   recursive subroutine consume(spec, cmd, cur, parsed, item, error)
      character(len=*), intent(in) :: spec
      type(command_def_t), intent(in) :: cmd
      type(cursor_t), intent(inout) :: cur
      type(parsed_t), intent(inout) :: parsed
      integer, intent(in) :: item
      type(error_t), allocatable, intent(out) :: error
      integer :: j, close, it0, nv0, count0
      logical :: repeat
      character :: c
      j = 1
      do while (j <= len(spec))
         c = spec(j:j)
         if (c == '[') then
            close = matching_bracket(spec, j)
            repeat = .false.
            if (close < len(spec)) repeat = spec(close + 1:close + 1) == '*'
            do
               if (.not. can_start(first_letter(spec(j + 1:close - 1)), cmd, cur)) exit
               it0 = cur%it
               nv0 = parsed%nvalues
               count0 = parsed%items(item)%count
               call consume(spec(j + 1:close - 1), cmd, cur, parsed, item, error)
               if (allocated(error)) then
                  ! an optional group that cannot be completed is not taken when
                  ! its numbers can be the command's range given after the
                  ! keywords: PRINT ZONE STRESS 0 5 0 5 is the zone table in a
                  ! range, not PRINT STRESS's grid short of nx ny
                  if (.not. repeat .and. range_ahead(it0)) then
                     deallocate (error)
                     cur%it = it0
                     parsed%nvalues = nv0
                     parsed%items(item)%count = count0
                     exit
                  end if
                  return
               end if
               if (.not. repeat) exit
            end do
            j = close + 1
            if (repeat) j = j + 1
         else
            repeat = .false.
            if (j < len(spec)) repeat = spec(j + 1:j + 1) == '*'
            if (repeat) then
               do while (can_start(c, cmd, cur))
                  call consume_one(c, cur, parsed, item, error)
                  if (allocated(error)) return
               end do
               j = j + 2
            else
               call consume_one(c, cur, parsed, item, error)
               if (allocated(error)) return
               j = j + 1
            end if
         end if
      end do
   contains
      !> The tokens from `it` are a range the command may take after its
      !> keywords: REG / ANN, or exactly four numbers (then a word or the end).
      logical function range_ahead(it)
         integer, intent(in) :: it
         integer :: k
         range_ahead = .false.
         if (.not. trailing_range(cmd, cur%tokens(it)%text, parsed)) return
         if (is_range_word(cur%tokens(it)%text)) then
            range_ahead = .true.
            return
         end if
         k = it
         do while (k <= cur%ntokens)
            if (.not. looks_numeric(cur%tokens(k)%text)) exit
            k = k + 1
         end do
         range_ahead = k - it == 4
      end function range_ahead
   end subroutine consume

   !> What argument letter `c` (commands_grammar) stands for, in words: the
   !> "expected ..." of a parse error, HELP's "where" line and the legend of
   !> the command reference and the manual page (commands_help).
   pure function describe(c) result(text)
      character, intent(in) :: c
      character(len=:), allocatable :: text
      integer :: i
      text = 'more input'
      i = index(argument_letters, c)
      if (i > 0) text = trim(argument_words(i))
   end function describe

   !> Consume one item of kind `c`.
   subroutine consume_one(c, cur, parsed, item, error)
      character, intent(in) :: c
      type(cursor_t), intent(inout) :: cur
      type(parsed_t), intent(inout) :: parsed
      integer, intent(in) :: item
      type(error_t), allocatable, intent(out) :: error
      type(value_t) :: v
      integer :: status, first, last
      logical :: bad
      if (c == 'R') then
         call parse_range_tokens(cur%tokens, cur%it, cur%ntokens, cur%context, parsed%range, error)
         if (allocated(error)) return
         parsed%has_range = .true.
         return
      end if
      if (cur%it > cur%ntokens) then
         call set_error(error, cur%context//': expected '//describe(c)//' (line ended)')
         return
      end if
      associate (tok => cur%tokens(cur%it)%text, line => cur%line, tokens => cur%tokens)
         select case (c)
         case ('s')
            ! A file name runs to the next blank, so paths with / or = survive;
            ! a leading / (an absolute path) is a delimiter to the tokenizer and
            ! is taken back here.
            first = tokens(cur%it)%first
            do while (first > 1)
               if (line(first - 1:first - 1) /= '/') exit
               first = first - 1
            end do
            ! only when the slashes start a word (blank, = or line start before
            ! them): `SAVE/x` stays the file x
            if (first > 1 .and. first < tokens(cur%it)%first) then
               if (index(' '//char(9)//'=', line(first - 1:first - 1)) == 0) &
                  first = tokens(cur%it)%first
            end if
            last = tokens(cur%it)%first
            do while (last < len(line))
               if (line(last + 1:last + 1) == ' ' .or. line(last + 1:last + 1) == char(9)) exit
               last = last + 1
            end do
            v%kind = value_text
            v%text = line(first:last)
            ! a name in quotes (as other programs take it) is the text between
            ! them, blanks included: SAVE "my run.sav"
            if (line(first:first) == '"' .or. line(first:first) == "'") then
               last = index(line(first + 1:), line(first:first))
               if (last <= 1) then
                  call set_error(error, cur%context//': expected a file name between quotes, got '// &
                                 line(first:))
                  return
               end if
               last = first + last
               v%text = line(first + 1:last - 1)
            end if
            do while (cur%it <= cur%ntokens)
               if (tokens(cur%it)%first > last) exit
               cur%it = cur%it + 1
            end do
            call push_value(parsed, item, v)
            return
         case ('a')
            v%kind = value_text
            v%text = tok
         case ('t')
            ! the rest of the line as typed, commas and brackets and all (a
            ! title: `HEAD tunnel (no INSITU)` keeps both brackets); the
            ! delimiters between the command word and the title are not in it
            v%kind = value_text
            first = 1
            if (cur%it > 1) first = tokens(cur%it - 1)%last + 1
            v%text = trim(adjustl(line(first:)))
            do while (len(v%text) > 0)
               if (index(',=', v%text(1:1)) == 0) exit
               v%text = trim(adjustl(v%text(2:)))
            end do
            cur%it = cur%ntokens + 1
            call push_value(parsed, item, v)
            return
         case ('r', 'n', 'p', 'i', 'c', 'q')
            if (.not. looks_numeric(tok)) then
               call expected_got(c, tok, cur%context, error)
               return
            end if
            if (index('rnp', c) > 0) then
               v%kind = value_real
               call parse_real(tok, v%r, status)
            else
               v%kind = value_integer
               call parse_integer(tok, v%i, status)
            end if
            if (status /= number_ok) then
               call number_error(status, c, tok, cur%context, error)
               return
            end if
            ! n: not negative, p: positive, c: count (not negative), q: at least 1
            select case (c)
            case ('n')
               bad = v%r < 0.0_wp
            case ('p')
               bad = v%r <= 0.0_wp
            case ('c')
               bad = v%i < 0
            case ('q')
               bad = v%i < 1
            case default
               bad = .false.
            end select
            if (bad) then
               call expected_got(c, tok, cur%context, error)
               return
            end if
         end select
      end associate
      cur%it = cur%it + 1
      call push_value(parsed, item, v)
   end subroutine consume_one

   !> "<context>: expected <what c accepts>, got '<tok>'"
   subroutine expected_got(c, tok, context, error)
      character, intent(in) :: c
      character(len=*), intent(in) :: tok, context
      type(error_t), allocatable, intent(out) :: error
      call set_error(error, context//": expected "//describe(c)//", got '"//printable(tok)//"'")
   end subroutine expected_got

   subroutine number_error(status, c, tok, context, error)
      integer, intent(in) :: status
      character, intent(in) :: c
      character(len=*), intent(in) :: tok, context
      type(error_t), allocatable, intent(out) :: error
      select case (status)
      case (number_out_of_range)
         call set_error(error, context//": number '"//printable(tok)//"' is out of range")
      case (number_not_integer)
         call set_error(error, context//": expected "//describe(c)// &
                        " (no decimal point or exponent), got '"//printable(tok)//"'")
      case default
         call set_error(error, context//": malformed number '"//printable(tok)// &
                        "' (expected "//describe(c)//")")
      end select
   end subroutine number_error

   !> The shared range parser: `xl xu yl yu`, `REG x1,y1 .. x4,y4`, `ANN xc yc r1 r2`.
   !> Reversed limits (xl > xu or yl > yu) are refused, naming the pair: the
   !> manual's range is xl < x < xu (Section 4.1), which a reversed pair never
   !> holds, and a silent swap hid the slip (FIX 10 0 0 10 meant to fix x < 10?).
   !> WINDOW, STRESS, FFIELD and PLOT XWINDOW / YWINDOW refuse them the same way.
   !> Equal limits are accepted (the manual forbids them because its strict
   !> xl < x < xu would select nothing; the box is inclusive here:
   !> `BOUND 0,12 10,10` is the line y = 10).
   subroutine parse_range_tokens(tokens, it, ntokens, context, range, error)
      type(token_t), intent(in) :: tokens(:)
      integer, intent(inout) :: it
      integer, intent(in) :: ntokens
      character(len=*), intent(in) :: context
      type(range_t), intent(out) :: range
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: v(8)
      integer :: n, k, first
      character(len=:), allocatable :: what
      if (it > ntokens) then
         call set_error(error, context//': expected '//describe('R')//' (line ended)')
         return
      end if
      what = 'range'
      if (to_upper(tokens(it)%text) == 'RANGE') then
         it = it + 1
         if (it > ntokens) then
            call set_error(error, context//': expected '//describe('R')//' after RANGE (line ended)')
            return
         end if
      end if
      if (looks_numeric(tokens(it)%text)) then
         n = 4
         range%kind = range_box
      else if (match_name(to_upper(tokens(it)%text), 'REGION', 3)) then
         n = 8
         range%kind = range_region
         what = 'REG range'
         it = it + 1
      else if (match_name(to_upper(tokens(it)%text), 'ANNULUS', 3)) then
         n = 4
         range%kind = range_annulus
         what = 'ANN range'
         it = it + 1
      else
         call expected_got('R', tokens(it)%text, context, error)
         return
      end if
      first = it
      do k = 1, n
         if (it > ntokens) then
            call set_error(error, context//': '//what//' needs more numbers (line ended)')
            return
         end if
         call read_range_number(tokens(it)%text, v(k), context, what, error)
         if (allocated(error)) return
         it = it + 1
      end do
      select case (range%kind)
      case (range_box)
         do k = 1, 3, 2
            if (v(k) > v(k + 1)) then
               call set_error(error, context//': range '//trim(tokens(first)%text)//' '// &
                              trim(tokens(first + 1)%text)//' '//trim(tokens(first + 2)%text)// &
                              ' '//trim(tokens(first + 3)%text)//': '//merge('xl > xu', 'yl > yu', k == 1) &
                              //' (a range is xl xu yl yu, lower limit first: give '// &
                              trim(tokens(first + k)%text)//' '//trim(tokens(first + k - 1)%text)//')')
               return
            end if
         end do
         range%xl = v(1); range%xu = v(2); range%yl = v(3); range%yu = v(4)
      case (range_region)
         range%px = v(1:7:2)
         range%py = v(2:8:2)
      case (range_annulus)
         if (v(3) < 0.0_wp .or. v(4) <= v(3)) then
            call set_error(error, context//': ANN range needs 0 <= r1 < r2')
            return
         end if
         range%xc = v(1); range%yc = v(2); range%r1 = v(3); range%r2 = v(4)
      end select
   end subroutine parse_range_tokens

   subroutine read_range_number(tok, v, context, what, error)
      character(len=*), intent(in) :: tok, context, what
      real(wp), intent(out) :: v
      type(error_t), allocatable, intent(out) :: error
      integer :: status
      v = 0.0_wp
      if (.not. looks_numeric(tok)) then
         call set_error(error, context//': '//what//" expects a real number, got '"// &
                        printable(tok)//"'")
         return
      end if
      call parse_real(tok, v, status)
      if (status /= number_ok) call number_error(status, 'r', tok, context, error)
   end subroutine read_range_number

end module commands_parser
