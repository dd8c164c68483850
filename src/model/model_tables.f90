!> TABLE (UDEC manual (ICG1.5, 1989), Section 4.5, TABLE: "Table of values
!> can be input for use by various commands ... ntab is the table number and
!> x,y are pairs of values"; used by TADD, Section 7.4.1): tables 1 to
!> max_tables, each a list of (x, y) pairs with x increasing, kept in two
!> flat arrays (table k: entries start(k) .. start(k) + len(k) - 1).
module model_tables
   use core_kinds, only: wp, ip
   implicit none
   private
   public :: table_set_t, max_tables, table_store, table_value

   integer, parameter :: max_tables = 10

   type :: table_set_t
      integer :: len(max_tables) = 0             !< pairs of table k (0: not defined)
      integer(ip) :: ntot = 0                    !< pairs of all tables
      real(wp), allocatable :: x(:), y(:)        !< (ntot) the pairs, table by table
   end type table_set_t

contains

   !> First entry of table k in the flat arrays.
   pure integer function first(t, k)
      type(table_set_t), intent(in) :: t
      integer, intent(in) :: k
      first = sum(t%len(1:k - 1)) + 1
   end function first

   !> TABLE k: replace table k by the pairs (x, y).
   subroutine table_store(t, k, x, y)
      type(table_set_t), intent(inout) :: t
      integer, intent(in) :: k
      real(wp), intent(in) :: x(:), y(:)
      real(wp), allocatable :: nx(:), ny(:)
      integer :: a, n
      a = first(t, k)
      n = t%len(k)
      allocate (nx(t%ntot - n + size(x)), ny(t%ntot - n + size(x)))
      if (t%ntot > 0) then
         nx(1:a - 1) = t%x(1:a - 1)
         ny(1:a - 1) = t%y(1:a - 1)
      end if
      nx(a:a + size(x) - 1) = x
      ny(a:a + size(x) - 1) = y
      if (t%ntot > 0) then
         nx(a + size(x):) = t%x(a + n:t%ntot)
         ny(a + size(x):) = t%y(a + n:t%ntot)
      end if
      call move_alloc(nx, t%x)
      call move_alloc(ny, t%y)
      t%len(k) = size(x)
      t%ntot = size(t%x, kind=ip)
   end subroutine table_store

   !> y of table k at x: linear between the pairs, the end values beyond them.
   pure real(wp) function table_value(t, k, x) result(v)
      type(table_set_t), intent(in) :: t
      integer, intent(in) :: k
      real(wp), intent(in) :: x
      integer :: a, b, i
      a = first(t, k)
      b = a + t%len(k) - 1
      if (x <= t%x(a)) then
         v = t%y(a)
      else if (x >= t%x(b)) then
         v = t%y(b)
      else
         do i = a, b - 1
            if (x <= t%x(i + 1)) exit
         end do
         v = t%y(i) + (t%y(i + 1) - t%y(i))*(x - t%x(i))/(t%x(i + 1) - t%x(i))
      end if
   end function table_value

end module model_tables
