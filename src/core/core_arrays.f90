!> Growable arrays, the one set of helpers for the whole code (design: growth
!> by capacity doubling with move_alloc): `grow_array(a, n, m)` gives `a`
!> capacity m, keeps entries 1..n and zero-fills the rest (the entity lists of
!> src/model: blocks, corners, contacts, gridpoints, zones, boundary points,
!> ...); `grow_double(a)` doubles a work array (2 size + 16), keeping every
!> entry. Integer ids use integer(ip), which is the default integer kind
!> (core_kinds), so one integer version serves both.
module core_arrays
   use core_kinds, only: wp, ip
   implicit none
   private
   public :: grow_array, grow_double, push_back

   interface grow_array
      module procedure grow_real, grow_int, grow_log
   end interface grow_array

   interface grow_double
      module procedure double_real, double_int, double_log
   end interface grow_double

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

   subroutine double_real(a)
      real(wp), allocatable, intent(inout) :: a(:)
      call grow_real(a, size(a, kind=ip), 2_ip*size(a, kind=ip) + 16_ip)
   end subroutine double_real

   subroutine double_int(a)
      integer(ip), allocatable, intent(inout) :: a(:)
      call grow_int(a, size(a, kind=ip), 2_ip*size(a, kind=ip) + 16_ip)
   end subroutine double_int

   subroutine double_log(a)
      logical, allocatable, intent(inout) :: a(:)
      call grow_log(a, size(a, kind=ip), 2_ip*size(a, kind=ip) + 16_ip)
   end subroutine double_log

   !> Append v to list(1:n), doubling the capacity when full.
   subroutine push_back(list, n, v)
      integer(ip), allocatable, intent(inout) :: list(:)
      integer(ip), intent(inout) :: n
      integer(ip), intent(in) :: v
      if (n >= size(list, kind=ip)) call double_int(list)
      n = n + 1
      list(n) = v
   end subroutine push_back

end module core_arrays
