!> Line editing at the UDEC> prompt (core_lineedit.c): libedit's readline
!> when standard input and output are a terminal and udec was built with it,
!> plain reads otherwise. Completion words are the registry's command names
!> and keywords (commands_session registers them).
module core_lineedit
   use, intrinsic :: iso_c_binding, only: c_int, c_char
   implicit none
   private
   public :: lineedit_active, lineedit_read, lineedit_add_word

   !> longest line read at the prompt (the interpreter's own limit is lower)
   integer, parameter :: line_capacity = 65536

   interface
      integer(c_int) function c_active() bind(c, name='udec_lineedit_active')
         import :: c_int
      end function c_active
      integer(c_int) function c_read(prompt, plen, buf, cap) bind(c, name='udec_lineedit_read')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: prompt(*)
         integer(c_int), value :: plen
         character(kind=c_char), intent(out) :: buf(*)
         integer(c_int), value :: cap
      end function c_read
      subroutine c_add_word(word, length) bind(c, name='udec_lineedit_add_word')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: word(*)
         integer(c_int), value :: length
      end subroutine c_add_word
   end interface

contains

   !> Are prompt lines read with line editing?
   logical function lineedit_active()
      lineedit_active = c_active() /= 0_c_int
   end function lineedit_active

   !> One line at `prompt`; `eof` at Ctrl-D.
   subroutine lineedit_read(prompt, text, eof)
      character(len=*), intent(in) :: prompt
      character(len=:), allocatable, intent(out) :: text
      logical, intent(out) :: eof
      character(kind=c_char, len=:), allocatable :: buf
      integer(c_int) :: n
      allocate (character(kind=c_char, len=line_capacity) :: buf)
      n = c_read(prompt, int(len(prompt), c_int), buf, int(line_capacity, c_int))
      eof = n < 0
      if (eof) then
         text = ''
      else
         text = buf(1:n)
      end if
   end subroutine lineedit_read

   !> Offer `word` for tab completion.
   subroutine lineedit_add_word(word)
      character(len=*), intent(in) :: word
      call c_add_word(word, int(len_trim(word), c_int))
   end subroutine lineedit_add_word

end module core_lineedit
