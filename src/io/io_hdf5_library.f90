!> HDF5 library lifetime and version (the save/restart schema arrives with issue 5).
module io_hdf5_library
   use hdf5, only: h5open_f, h5close_f, h5get_libversion_f
   implicit none
   private
   public :: hdf5_version_string

contains

   !> "major.minor.release" of the linked HDF5 library, or "unavailable".
   function hdf5_version_string() result(text)
      character(len=:), allocatable :: text
      integer :: major, minor, release, status
      character(len=32) :: buf
      text = 'unavailable'
      call h5open_f(status)
      if (status /= 0) return
      call h5get_libversion_f(major, minor, release, status)
      if (status == 0) then
         write (buf, '(i0,".",i0,".",i0)') major, minor, release
         text = trim(buf)
      end if
      call h5close_f(status)
   end function hdf5_version_string

end module io_hdf5_library
