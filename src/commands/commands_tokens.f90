!> Tokenizer of UDEC input lines (manual Section 4.1). Delimiters are blanks,
!> tabs and ( ) , / = ; a `*` (or `;`) starts a comment that runs to the end of the line.
module commands_tokens
   use core_strings, only: to_upper, to_lower
   implicit none
   private
   public :: token_t, tokenize, strip_comment, to_upper, to_lower, is_delimiter, printable
   public :: substituted

   !> One token: its text and where it sits in the line (1-based columns).
   type :: token_t
      character(len=:), allocatable :: text
      integer :: first = 0
      integer :: last = 0
   end type token_t

contains

   pure logical function is_delimiter(c)
      character, intent(in) :: c
      select case (c)
      case (' ', char(9), '(', ')', ',', '/', '=', char(13), char(0))
         is_delimiter = .true.
      case default
         is_delimiter = .false.
      end select
   end function is_delimiter

   !> The part of `line` before its first `*` (the manual's comment marker,
   !> Section 4.1) or `;` (the comment marker of Itasca's later codes: a user
   !> who writes `CYCLE 100 ; run it` means a comment, and `;` has no other
   !> use in the command language; HEADING's title is read as typed).
   pure function strip_comment(line) result(code)
      character(len=*), intent(in) :: line
      character(len=:), allocatable :: code
      integer :: k
      k = scan(line, '*;')
      if (k > 0) then
         code = line(1:k - 1)
      else
         code = line
      end if
   end function strip_comment

   !> Split `line` (comment already stripped) into tokens.
   subroutine tokenize(line, tokens, ntokens)
      character(len=*), intent(in) :: line
      type(token_t), allocatable, intent(inout) :: tokens(:)
      integer, intent(out) :: ntokens
      integer :: i, n, start
      type(token_t), allocatable :: grown(:)
      ntokens = 0
      if (.not. allocated(tokens)) allocate (tokens(16))
      n = len(line)
      i = 1
      do while (i <= n)
         if (is_delimiter(line(i:i))) then
            i = i + 1
            cycle
         end if
         start = i
         do while (i <= n)
            if (is_delimiter(line(i:i))) exit
            i = i + 1
         end do
         if (ntokens == size(tokens)) then
            allocate (grown(2*size(tokens)))
            grown(1:ntokens) = tokens(1:ntokens)
            call move_alloc(grown, tokens)
         end if
         ntokens = ntokens + 1
         tokens(ntokens)%text = line(start:i - 1)
         tokens(ntokens)%first = start
         tokens(ntokens)%last = i - 1
      end do
   end subroutine tokenize

   !> `text` with control and non-ASCII bytes replaced by '?', cut to 60 chars,
   !> for quoting user input in messages.
   pure function printable(text) result(clean)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: clean
      integer :: i, c, n
      n = min(len(text), 60)
      clean = text(1:n)
      do i = 1, n
         c = ichar(clean(i:i))
         if (c < 32 .or. c > 126) clean(i:i) = '?'
      end do
      if (len(text) > n) clean = clean//'...'
   end function printable

   !> `text` with each character of `chars` replaced by its string in `by`:
   !> the k-th character by `by((k-1)*width+1:k*width)` (the escapes of HELP's
   !> roff page and of EXPORT's XML comments).
   pure function substituted(text, chars, by, width) result(out)
      character(len=*), intent(in) :: text, chars, by
      integer, intent(in) :: width
      character(len=:), allocatable :: out
      integer :: i, k
      out = ''
      do i = 1, len(text)
         k = index(chars, text(i:i))
         if (k == 0) then
            out = out//text(i:i)
         else
            out = out//by((k - 1)*width + 1:k*width)
         end if
      end do
   end function substituted

end module commands_tokens
