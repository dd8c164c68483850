!> Sorting, one implementation for the whole code: a stable merge sort that
!> returns the permutation (`order`) putting keys in ascending order; equal
!> keys keep their input order, so results do not depend on the algorithm.
!> The comparison is written inline (no procedure argument): contact
!> updates sort every contact pair during a CYCLE.
module core_sort
   use core_kinds, only: wp, ip
   implicit none
   private
   public :: sort_order, sort_order_pairs, sort_values, counts_to_starts, lower_bound

   !> sort_order(keys, order): keys(order) ascending (real or integer keys).
   interface sort_order
      module procedure order_real, order_int
   end interface sort_order

contains

   !> Bucket starts from bucket sizes (the index of a bucket sort, CSR):
   !> on entry start(k + 1) is the size of bucket k; on return start(k) is
   !> the first slot of bucket k and start(size(start)) one past the last.
   pure subroutine counts_to_starts(start)
      integer(ip), intent(inout) :: start(:)
      integer(ip) :: k
      start(1) = 1
      do k = 1, size(start, kind=ip) - 1
         start(k + 1) = start(k + 1) + start(k)
      end do
   end subroutine counts_to_starts

   subroutine order_real(keys, order)
      real(wp), intent(in) :: keys(:)
      integer(ip), intent(out) :: order(:)
      real(wp), allocatable :: zero(:)
      allocate (zero(size(keys)))
      zero = 0.0_wp
      call merge_order(keys, zero, order)
   end subroutine order_real

   !> Integer keys (integer(ip) is exact in real(wp)).
   subroutine order_int(keys, order)
      integer(ip), intent(in) :: keys(:)
      integer(ip), intent(out) :: order(:)
      call order_real(real(keys, wp), order)
   end subroutine order_int

   !> First slot of the ascending `keys` whose key is not below x
   !> (size(keys) + 1 if none): binary search.
   pure integer(ip) function lower_bound(keys, x) result(lo)
      real(wp), intent(in) :: keys(:)
      real(wp), intent(in) :: x
      integer(ip) :: hi, mid
      lo = 1
      hi = size(keys, kind=ip) + 1
      do while (lo < hi)
         mid = (lo + hi)/2
         if (keys(mid) < x) then
            lo = mid + 1
         else
            hi = mid
         end if
      end do
   end function lower_bound

   !> Sort real values in place, ascending.
   subroutine sort_values(a)
      real(wp), intent(inout) :: a(:)
      integer(ip), allocatable :: order(:)
      allocate (order(size(a)))
      call order_real(a, order)
      a = a(order)
   end subroutine sort_values

   !> (key1, key2)(order) in lexicographic ascending order.
   subroutine sort_order_pairs(key1, key2, order)
      integer(ip), intent(in) :: key1(:), key2(:)
      integer(ip), intent(out) :: order(:)
      call merge_order(real(key1, wp), real(key2, wp), order)
   end subroutine sort_order_pairs

   !> Stable merge sort of 1..n by (k1, k2), lexicographic.
   subroutine merge_order(k1, k2, order)
      real(wp), intent(in) :: k1(:), k2(:)
      integer(ip), intent(out) :: order(:)
      integer(ip), allocatable :: tmp(:)
      integer(ip) :: i, n
      n = size(k1, kind=ip)
      do i = 1, n
         order(i) = i
      end do
      allocate (tmp(n))
      call merge_range(1_ip, n)
   contains
      recursive subroutine merge_range(lo, hi)
         integer(ip), intent(in) :: lo, hi
         integer(ip) :: mid, i1, i2, k, a, b
         if (hi - lo < 1) return
         mid = (lo + hi)/2
         call merge_range(lo, mid)
         call merge_range(mid + 1, hi)
         i1 = lo
         i2 = mid + 1
         do k = lo, hi
            if (i2 > hi) then
               tmp(k) = order(i1); i1 = i1 + 1
            else if (i1 > mid) then
               tmp(k) = order(i2); i2 = i2 + 1
            else
               a = order(i1)
               b = order(i2)
               if (k1(a) < k1(b) .or. (k1(a) == k1(b) .and. k2(a) <= k2(b))) then
                  tmp(k) = a; i1 = i1 + 1
               else
                  tmp(k) = b; i2 = i2 + 1
               end if
            end if
         end do
         order(lo:hi) = tmp(lo:hi)
      end subroutine merge_range
   end subroutine merge_order

end module core_sort
