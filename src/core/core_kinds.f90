!> Numeric kinds used everywhere in udec.
module core_kinds
   use, intrinsic :: iso_fortran_env, only: real64, int8, int32, int64
   use, intrinsic :: iso_c_binding, only: c_bool
   implicit none
   private
   public :: wp, ip, i8, i1, l1

   integer, parameter :: wp = real64   !< working real precision
   integer, parameter :: ip = int32    !< default integer (ids, counts)
   integer, parameter :: i8 = int64    !< long integer (cycle counts, seeds)
   !> one-byte codes of large lists (a contact's kind and JCONS: issue 23)
   integer, parameter :: i1 = int8     !< small code (values -128 .. 127)
   !> one-byte logical of large work lists (a contact's void mark: issue 23)
   integer, parameter :: l1 = c_bool
end module core_kinds
