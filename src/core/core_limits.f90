!> Limits on what a typed count may allocate (issue 20): a request above a
!> documented limit or above the memory the system has free is refused
!> before anything is allocated, with a message naming the size it needs.
module core_limits
   use core_kinds, only: wp, i8
   use core_error, only: error_t, set_error
   use core_output, only: format_real
   implicit none
   private
   public :: check_request, memory_available, bytes_text, max_material_number

   !> Highest material number PROPERTY accepts (a table of
   !> 45 properties per number; the manual's decks use numbers below 100).
   integer, parameter :: max_material_number = 10000

contains

   !> Refuse (error naming `what`, the count and the bytes) when `count`
   !> exceeds `limit` or `count*bytes_each` exceeds the free memory.
   !> `what` reads like 'PROPERTY: material number'.
   subroutine check_request(what, count, bytes_each, limit, error)
      character(len=*), intent(in) :: what
      real(wp), intent(in) :: count, bytes_each
      real(wp), intent(in) :: limit
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: need, free
      need = count*bytes_each
      if (.not. count <= limit) then
         call set_error(error, what//' '//count_text(count)//' is above the limit of '// &
                        count_text(limit)//' (it would need '//bytes_text(need)//')')
         return
      end if
      free = memory_available()
      if (free > 0.0_wp .and. need > free) then
         call set_error(error, what//' '//count_text(count)//' would need '// &
                        bytes_text(need)//', more than the '//bytes_text(free)//' of free memory')
      end if
   end subroutine check_request

   !> Bytes of memory available (MemAvailable of /proc/meminfo); 0 when unknown.
   real(wp) function memory_available() result(bytes)
      character(len=256) :: line
      integer :: unit, ios
      integer(i8) :: kb
      bytes = 0.0_wp
      open (newunit=unit, file='/proc/meminfo', status='old', action='read', iostat=ios)
      if (ios /= 0) return
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (line(1:13) == 'MemAvailable:') then
            read (line(14:), *, iostat=ios) kb
            if (ios == 0) bytes = 1024.0_wp*real(kb, wp)
            exit
         end if
      end do
      close (unit)
   end function memory_available

   !> A count as typed: digits when it is a whole number of at most 18 digits.
   function count_text(count) result(text)
      real(wp), intent(in) :: count
      character(len=:), allocatable :: text
      character(len=24) :: buf
      if (abs(count) < 1.0e18_wp .and. count == aint(count)) then
         write (buf, '(i0)') int(count, i8)
         text = trim(buf)
      else
         text = trim(format_real(count))
      end if
   end function count_text

   !> '36 GB', '512 kB': a size for messages.
   function bytes_text(bytes) result(text)
      real(wp), intent(in) :: bytes
      character(len=:), allocatable :: text
      character(len=*), parameter :: units(5) = ['bytes', 'kB   ', 'MB   ', 'GB   ', 'TB   ']
      real(wp) :: v
      integer :: k
      v = bytes
      k = 1
      do while (v >= 1000.0_wp .and. k < size(units))
         v = v/1000.0_wp
         k = k + 1
      end do
      text = trim(format_real(real(nint(10.0_wp*v), wp)/10.0_wp))//' '//trim(units(k))
   end function bytes_text

end module core_limits
