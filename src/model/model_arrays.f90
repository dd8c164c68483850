!> Capacity growth of the structure-of-arrays entity lists (design: growth
!> by capacity doubling with move_alloc): `grow_array(a, n, m)` gives `a`
!> capacity m, keeps entries 1..n and zero-fills the rest. One generic for
!> every list in src/model (blocks, corners, contacts, gridpoints, zones,
!> boundary points, ...). Integer ids use integer(ip), which is the
!> default integer kind (core_kinds), so one integer version serves both.
module model_arrays
   use core_kinds, only: wp, ip
   implicit none
   private
   public :: grow_array

   interface grow_array
      module procedure grow_real, grow_int, grow_log
   end interface grow_array

contains

   subroutine grow_real(a, n, m)
      real(wp), allocatable, intent(inout) :: a(:)
      integer(ip), intent(in) :: n, m
      real(wp), allocatable :: t(:)
      allocate (t(m))
      t = 0.0_wp
      if (allocated(a) .and. n > 0) t(1:n) = a(1:n)
      call move_alloc(t, a)
   end subroutine grow_real

   subroutine grow_int(a, n, m)
      integer(ip), allocatable, intent(inout) :: a(:)
      integer(ip), intent(in) :: n, m
      integer(ip), allocatable :: t(:)
      allocate (t(m))
      t = 0
      if (allocated(a) .and. n > 0) t(1:n) = a(1:n)
      call move_alloc(t, a)
   end subroutine grow_int

   subroutine grow_log(a, n, m)
      logical, allocatable, intent(inout) :: a(:)
      integer(ip), intent(in) :: n, m
      logical, allocatable :: t(:)
      allocate (t(m))
      t = .false.
      if (allocated(a) .and. n > 0) t(1:n) = a(1:n)
      call move_alloc(t, a)
   end subroutine grow_log

end module model_arrays
