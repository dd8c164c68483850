!> Small text helpers shared by the command layer and the property tables.
module core_strings
   implicit none
   private
   public :: edit_distance

contains

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

end module core_strings
