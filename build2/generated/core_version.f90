!> Program version and build information (configured by CMake).
module core_version
   implicit none
   private
   public :: udec_version, udec_name, udec_license

   character(len=*), parameter :: udec_version = "0.1.0"
   character(len=*), parameter :: udec_name = "udec"
   !> the licence of the program (the file LICENSE)
   character(len=*), parameter :: udec_license = "BSD-3-Clause"
end module core_version
