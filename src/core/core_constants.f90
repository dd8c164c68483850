!> Mathematical constants, defined once.
module core_constants
   use core_kinds, only: wp
   implicit none
   private
   real(wp), parameter, public :: pi = 3.14159265358979323846_wp
   real(wp), parameter, public :: two_pi = 2.0_wp*pi
end module core_constants
