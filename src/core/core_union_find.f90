!> Disjoint sets over 1..n held in one array: root(a) == a at a set's
!> representative. Joining keeps the smaller representative, so the
!> representatives do not depend on the order of the joins' arguments.
!> Used where items are grouped by pairwise links (INSITU's joint chains,
!> the thermal mesh's coincident boundary points).
module core_union_find
   use core_kinds, only: ip
   implicit none
   private
   public :: union_find_root, union_find_join

contains

   !> Representative of a's set; halves the path on the way.
   integer(ip) function union_find_root(root, a) result(q)
      integer(ip), intent(inout) :: root(:)
      integer(ip), intent(in) :: a
      q = a
      do while (root(q) /= q)
         root(q) = root(root(q))
         q = root(q)
      end do
   end function union_find_root

   !> Join the sets of a and b.
   subroutine union_find_join(root, a, b)
      integer(ip), intent(inout) :: root(:)
      integer(ip), intent(in) :: a, b
      integer(ip) :: ra, rb
      ra = union_find_root(root, a)
      rb = union_find_root(root, b)
      if (ra /= rb) root(max(ra, rb)) = min(ra, rb)
   end subroutine union_find_join

end module core_union_find
