!> Small text helpers shared by the command layer, the property tables and
!> the plot devices.
module core_strings
   implicit none
   private
   public :: edit_distance, to_upper, to_lower, table_text, text_pair_t

   !> One row of a lookup table: a word and the text it stands for.
   type :: text_pair_t
      character(len=16) :: key = ''
      character(len=48) :: text = ''
   end type text_pair_t

contains

   !> `text` with the ASCII letters a-z in upper case (UDEC words are upper case).
   pure function to_upper(text) result(upper)
      character(len=*), intent(in) :: text
      character(len=len(text)) :: upper
      integer :: i, c
      upper = text
      do i = 1, len(text)
         c = ichar(text(i:i))
         if (c >= ichar('a') .and. c <= ichar('z')) upper(i:i) = char(c - 32)
      end do
   end function to_upper

   !> `text` with the ASCII letters A-Z in lower case.
   pure function to_lower(text) result(low)
      character(len=*), intent(in) :: text
      character(len=len(text)) :: low
      integer :: i
      low = text
      do i = 1, len(text)
         if (text(i:i) >= 'A' .and. text(i:i) <= 'Z') low(i:i) = achar(iachar(text(i:i)) + 32)
      end do
   end function to_lower

   !> Levenshtein distance between `a` and `b` (insert, delete, substitute);
   !> used to name the known words closest to a misspelt one.
   pure integer function edit_distance(a, b) result(d)
      character(len=*), intent(in) :: a, b
      integer :: prev(0:len(b)), cur(0:len(b)), i, j, cost
      do j = 0, len(b)
         prev(j) = j
      end do
      do i = 1, len(a)
         cur(0) = i
         do j = 1, len(b)
            cost = merge(0, 1, a(i:i) == b(j:j))
            cur(j) = min(prev(j) + 1, cur(j - 1) + 1, prev(j - 1) + cost)
         end do
         prev = cur
      end do
      d = prev(len(b))
   end function edit_distance

   !> The text that a table of pairs gives `key`: the text (trailing blanks
   !> removed) of the first pair whose key is `key`, else `default`. Lets a
   !> label lookup be a parameter table rather than a `select case`.
   pure function table_text(table, key, default) result(text)
      type(text_pair_t), intent(in) :: table(:)
      character(len=*), intent(in) :: key, default
      character(len=:), allocatable :: text
      integer :: i
      do i = 1, size(table)
         if (table(i)%key == key) then
            text = trim(table(i)%text)
            return
         end if
      end do
      text = default
   end function table_text

end module core_strings
