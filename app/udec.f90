!> udec main program: placeholder until the interpreter lands.
program udec
   use core_version, only: udec_version
   implicit none
   write (*, '(a)') 'udec '//udec_version
end program udec
