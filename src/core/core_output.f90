!> Where program text goes: the screen, the batch OUT file, the UDEC.LOG file
!> and PRINT FILE redirection. An `output_t` is passed explicitly to whatever
!> writes; it owns no model state.
module core_output
   use, intrinsic :: iso_fortran_env, only: output_unit
   use core_kinds, only: wp
   implicit none
   private
   public :: output_t, max_sinks, printable

   integer, parameter :: max_sinks = 4

   !> A set of open units that every line is written to.
   type :: output_t
      integer :: nsink = 0
      integer :: unit(max_sinks) = -1
      logical :: screen = .true.     !< also write to standard output
   contains
      procedure :: line => output_line
      procedure :: add_unit => output_add_unit
      procedure :: remove_unit => output_remove_unit
   end type output_t

contains

   !> A value as the printed tables show it. An `esW.D` edit descriptor
   !> writes exponents beyond +-99 without the letter E (1.23456-102), which
   !> no reader takes for a number; magnitudes below 1e-99 (the numerical
   !> dust of a wave front, physically zero) print as 0 and finite ones above
   !> 9.99999e99 as +-9.99999e99. NaN and infinities pass through (they print
   !> as NaN / Infinity).
   elemental real(wp) function printable(x) result(y)
      real(wp), intent(in) :: x
      real(wp), parameter :: big = 9.99999e99_wp
      y = x
      if (abs(x) < 1.0e-99_wp) then
         y = 0.0_wp
      else if (abs(x) > big .and. abs(x) <= huge(x)) then
         y = sign(big, x)
      end if
   end function printable

   !> Write one line of text to every sink.
   subroutine output_line(this, text)
      class(output_t), intent(in) :: this
      character(len=*), intent(in) :: text
      integer :: i
      if (this%screen) then
         write (output_unit, '(a)') trim(text)
         flush (output_unit)
      end if
      do i = 1, this%nsink
         write (this%unit(i), '(a)') trim(text)
      end do
   end subroutine output_line

   !> Add an open unit as a sink (ignored when already present or full).
   subroutine output_add_unit(this, unit)
      class(output_t), intent(inout) :: this
      integer, intent(in) :: unit
      if (any(this%unit(1:this%nsink) == unit)) return
      if (this%nsink >= max_sinks) return
      this%nsink = this%nsink + 1
      this%unit(this%nsink) = unit
   end subroutine output_add_unit

   !> Remove a unit from the sinks (the caller closes it).
   subroutine output_remove_unit(this, unit)
      class(output_t), intent(inout) :: this
      integer, intent(in) :: unit
      integer :: i, j
      j = 0
      do i = 1, this%nsink
         if (this%unit(i) /= unit) then
            j = j + 1
            this%unit(j) = this%unit(i)
         end if
      end do
      this%unit(j + 1:) = -1
      this%nsink = j
   end subroutine output_remove_unit

end module core_output
