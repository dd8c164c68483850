!> File helpers: output files are written to a temporary beside the target and
!> renamed into place, so a reader never sees a half-written file.
module core_files
   use, intrinsic :: iso_c_binding, only: c_char, c_int, c_null_char
   implicit none
   private
   public :: file_rename, file_delete, temporary_name

   interface
      !> C library rename(3): replaces `new` atomically on POSIX systems.
      function c_rename(old, new) bind(c, name='rename') result(status)
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: old(*), new(*)
         integer(c_int) :: status
      end function c_rename
   end interface

contains

   !> Name of the temporary written before `name` is renamed into place.
   pure function temporary_name(name) result(temp)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: temp
      temp = name//'.udec-tmp'
   end function temporary_name

   !> Rename file `from` to `to` (replacing `to`); `ok` false on failure.
   subroutine file_rename(from, to, ok)
      character(len=*), intent(in) :: from, to
      logical, intent(out) :: ok
      ok = c_rename(from//c_null_char, to//c_null_char) == 0_c_int
   end subroutine file_rename

   !> Delete file `name` if it exists.
   subroutine file_delete(name)
      character(len=*), intent(in) :: name
      integer :: u, ios
      logical :: exists
      inquire (file=name, exist=exists)
      if (.not. exists) return
      open (newunit=u, file=name, status='old', iostat=ios)
      if (ios == 0) close (u, status='delete', iostat=ios)
   end subroutine file_delete

end module core_files
