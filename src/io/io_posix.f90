!> The few C library calls SAVE needs besides core_files (rename): the process
!> id (for a temporary name next to the target) and unlink (to clean up after
!> a failed write).
module io_posix
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
   implicit none
   private
   public :: posix_getpid, posix_unlink, ignore_file_size_signal

   interface
      integer(c_int) function c_getpid() bind(c, name='getpid')
         import :: c_int
      end function c_getpid
      integer(c_int) function c_unlink(path) bind(c, name='unlink')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
      end function c_unlink
      !> io_signals.c
      subroutine udec_ignore_file_size_signal() bind(c, name='udec_ignore_file_size_signal')
      end subroutine udec_ignore_file_size_signal
   end interface

contains

   !> Id of this process.
   integer function posix_getpid() result(pid)
      pid = int(c_getpid())
   end function posix_getpid

   !> Remove the file `path`; .true. on success.
   logical function posix_unlink(path) result(ok)
      character(len=*), intent(in) :: path
      ok = c_unlink(path//c_null_char) == 0_c_int
   end function posix_unlink

   !> A file size limit makes writes fail (an error SAVE reports) instead of
   !> ending the program with SIGXFSZ. Called once by the main program.
   subroutine ignore_file_size_signal()
      call udec_ignore_file_size_signal()
   end subroutine ignore_file_size_signal

end module io_posix
