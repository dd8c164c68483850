!> Growable arrays, the one set of helpers for the whole code (design: growth
!> by capacity doubling with move_alloc): `grow_array(a, n, m)` gives `a`
!> capacity m, keeps entries 1..n and zero-fills the rest (the entity lists of
!> src/model: blocks, corners, contacts, gridpoints, zones, boundary points,
!> ...); `grow_double(a)` doubles a work array (2 size + 16), keeping every
!> entry. `grow_lists(n, m, a1, a2, ..)` does grow_array for up to 16 arrays
!> of one kind at once (the fields of one entity list). Integer ids use
!> integer(ip), which is the default integer kind (core_kinds), so one integer
!> version serves both.
module core_arrays
   use core_kinds, only: wp, ip
   implicit none
   private
   public :: grow_array, grow_double, push_back, grow_lists

   interface grow_array
      module procedure grow_real, grow_int, grow_log
   end interface grow_array

   interface grow_lists
      module procedure grow_reals, grow_ints, grow_logs
   end interface grow_lists

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

   subroutine grow_reals(n, m, a1, a2, a3, a4, a5, a6, a7, a8, &
                         a9, a10, a11, a12, a13, a14, a15, a16)
      integer(ip), intent(in) :: n, m
      real(wp), allocatable, intent(inout) :: a1(:)
      real(wp), allocatable, intent(inout), optional :: a2(:), a3(:), a4(:), a5(:), a6(:), &
         a7(:), a8(:), a9(:), a10(:), a11(:), a12(:), a13(:), a14(:), a15(:), a16(:)
      call grow_real(a1, n, m)
      if (present(a2)) call grow_real(a2, n, m)
      if (present(a3)) call grow_real(a3, n, m)
      if (present(a4)) call grow_real(a4, n, m)
      if (present(a5)) call grow_real(a5, n, m)
      if (present(a6)) call grow_real(a6, n, m)
      if (present(a7)) call grow_real(a7, n, m)
      if (present(a8)) call grow_real(a8, n, m)
      if (present(a9)) call grow_real(a9, n, m)
      if (present(a10)) call grow_real(a10, n, m)
      if (present(a11)) call grow_real(a11, n, m)
      if (present(a12)) call grow_real(a12, n, m)
      if (present(a13)) call grow_real(a13, n, m)
      if (present(a14)) call grow_real(a14, n, m)
      if (present(a15)) call grow_real(a15, n, m)
      if (present(a16)) call grow_real(a16, n, m)
   end subroutine grow_reals

   subroutine grow_ints(n, m, a1, a2, a3, a4, a5, a6, a7, a8, &
                         a9, a10, a11, a12, a13, a14, a15, a16)
      integer(ip), intent(in) :: n, m
      integer(ip), allocatable, intent(inout) :: a1(:)
      integer(ip), allocatable, intent(inout), optional :: a2(:), a3(:), a4(:), a5(:), a6(:), &
         a7(:), a8(:), a9(:), a10(:), a11(:), a12(:), a13(:), a14(:), a15(:), a16(:)
      call grow_int(a1, n, m)
      if (present(a2)) call grow_int(a2, n, m)
      if (present(a3)) call grow_int(a3, n, m)
      if (present(a4)) call grow_int(a4, n, m)
      if (present(a5)) call grow_int(a5, n, m)
      if (present(a6)) call grow_int(a6, n, m)
      if (present(a7)) call grow_int(a7, n, m)
      if (present(a8)) call grow_int(a8, n, m)
      if (present(a9)) call grow_int(a9, n, m)
      if (present(a10)) call grow_int(a10, n, m)
      if (present(a11)) call grow_int(a11, n, m)
      if (present(a12)) call grow_int(a12, n, m)
      if (present(a13)) call grow_int(a13, n, m)
      if (present(a14)) call grow_int(a14, n, m)
      if (present(a15)) call grow_int(a15, n, m)
      if (present(a16)) call grow_int(a16, n, m)
   end subroutine grow_ints

   subroutine grow_logs(n, m, a1, a2, a3, a4, a5, a6, a7, a8, &
                         a9, a10, a11, a12, a13, a14, a15, a16)
      integer(ip), intent(in) :: n, m
      logical, allocatable, intent(inout) :: a1(:)
      logical, allocatable, intent(inout), optional :: a2(:), a3(:), a4(:), a5(:), a6(:), &
         a7(:), a8(:), a9(:), a10(:), a11(:), a12(:), a13(:), a14(:), a15(:), a16(:)
      call grow_log(a1, n, m)
      if (present(a2)) call grow_log(a2, n, m)
      if (present(a3)) call grow_log(a3, n, m)
      if (present(a4)) call grow_log(a4, n, m)
      if (present(a5)) call grow_log(a5, n, m)
      if (present(a6)) call grow_log(a6, n, m)
      if (present(a7)) call grow_log(a7, n, m)
      if (present(a8)) call grow_log(a8, n, m)
      if (present(a9)) call grow_log(a9, n, m)
      if (present(a10)) call grow_log(a10, n, m)
      if (present(a11)) call grow_log(a11, n, m)
      if (present(a12)) call grow_log(a12, n, m)
      if (present(a13)) call grow_log(a13, n, m)
      if (present(a14)) call grow_log(a14, n, m)
      if (present(a15)) call grow_log(a15, n, m)
      if (present(a16)) call grow_log(a16, n, m)
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
