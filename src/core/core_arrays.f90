!> Growable arrays, the one set of helpers for the whole code (design: growth
!> by capacity doubling with move_alloc; the entity lists of blocks, corners
!> and contacts grow by a quarter, `list_capacity`, and give back their slack
!> after detection, model_geometry): `grow_array(a, n, m)` gives `a`
!> capacity m, keeps entries 1..n and zero-fills the rest (the entity lists of
!> src/model: blocks, corners, contacts, gridpoints, zones, boundary points,
!> ...); `grow_double(a)` doubles a work array (2 size + 16), keeping every
!> entry. `grow_lists(n, m, a1, a2, ..)` does grow_array for up to 16 arrays
!> of one kind at once (the fields of one entity list). Integer ids use
!> integer(ip), which is the default integer kind (core_kinds), so one integer
!> version serves both.
module core_arrays
   use core_kinds, only: wp, ip, i1, l1
   implicit none
   private
   public :: grow_array, grow_double, push_back, grow_lists, list_capacity

   interface grow_array
      module procedure grow_real, grow_int, grow_log, grow_int1, grow_log1
   end interface grow_array

   interface grow_lists
      module procedure grow_reals, grow_ints, grow_logs
   end interface grow_lists

   interface grow_double
      module procedure double_real, double_int, double_log
   end interface grow_double

contains

   !> Capacity for a list of capacity `cap` that must hold `need` entries: a
   !> quarter more than it has (and at least 64 more), or `need` if larger.
   !> Growth by a quarter keeps the copying amortised (each entry is copied
   !> about four times over the list's life) and leaves at most a fifth of
   !> the slots empty, where doubling leaves up to half (issue 23: 2^20
   !> contact slots for 600 400 contacts).
   pure integer(ip) function list_capacity(cap, need) result(m)
      integer(ip), intent(in) :: cap, need
      m = max(need, cap + cap/4_ip + 64_ip)
   end function list_capacity

   ! One body per operation, included once per kind (core_arrays_*.inc): a
   ! kind's version declares `a` / `a1..a16`, the work array `t` and the
   ! fill value of new entries, and the body does the rest.

   subroutine grow_real(a, n, m)
      real(wp), allocatable, intent(inout) :: a(:)
      real(wp), allocatable :: t(:)
      real(wp), parameter :: fill = 0.0_wp
      include 'core_arrays_grow.inc'
   end subroutine grow_real

   subroutine grow_int(a, n, m)
      integer(ip), allocatable, intent(inout) :: a(:)
      integer(ip), allocatable :: t(:)
      integer(ip), parameter :: fill = 0_ip
      include 'core_arrays_grow.inc'
   end subroutine grow_int

   subroutine grow_log(a, n, m)
      logical, allocatable, intent(inout) :: a(:)
      logical, allocatable :: t(:)
      logical, parameter :: fill = .false.
      include 'core_arrays_grow.inc'
   end subroutine grow_log

   subroutine grow_int1(a, n, m)
      integer(i1), allocatable, intent(inout) :: a(:)
      integer(i1), allocatable :: t(:)
      integer(i1), parameter :: fill = 0_i1
      include 'core_arrays_grow.inc'
   end subroutine grow_int1

   subroutine grow_log1(a, n, m)
      logical(l1), allocatable, intent(inout) :: a(:)
      logical(l1), allocatable :: t(:)
      logical(l1), parameter :: fill = .false.
      include 'core_arrays_grow.inc'
   end subroutine grow_log1

   subroutine grow_reals(n, m, a1, a2, a3, a4, a5, a6, a7, a8, &
                         a9, a10, a11, a12, a13, a14, a15, a16)
      real(wp), allocatable, intent(inout) :: a1(:)
      real(wp), allocatable, intent(inout), optional :: a2(:), a3(:), a4(:), a5(:), a6(:), &
         a7(:), a8(:), a9(:), a10(:), a11(:), a12(:), a13(:), a14(:), a15(:), a16(:)
      include 'core_arrays_grow_lists.inc'
   end subroutine grow_reals

   subroutine grow_ints(n, m, a1, a2, a3, a4, a5, a6, a7, a8, &
                        a9, a10, a11, a12, a13, a14, a15, a16)
      integer(ip), allocatable, intent(inout) :: a1(:)
      integer(ip), allocatable, intent(inout), optional :: a2(:), a3(:), a4(:), a5(:), a6(:), &
         a7(:), a8(:), a9(:), a10(:), a11(:), a12(:), a13(:), a14(:), a15(:), a16(:)
      include 'core_arrays_grow_lists.inc'
   end subroutine grow_ints

   subroutine grow_logs(n, m, a1, a2, a3, a4, a5, a6, a7, a8, &
                        a9, a10, a11, a12, a13, a14, a15, a16)
      logical(l1), allocatable, intent(inout) :: a1(:)
      logical(l1), allocatable, intent(inout), optional :: a2(:), a3(:), a4(:), a5(:), a6(:), &
         a7(:), a8(:), a9(:), a10(:), a11(:), a12(:), a13(:), a14(:), a15(:), a16(:)
      include 'core_arrays_grow_lists.inc'
   end subroutine grow_logs

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
