!> Interrupts (SIGINT, SIGTERM): core_signals.c raises a flag; the cycle
!> loops poll `interrupt_pending` once a step and end there, the interpreter
!> decides what follows (back to the prompt, or end of a batch run).
module core_interrupt
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
   implicit none
   private
   public :: interrupt_install, interrupt_pending, interrupt_signal, interrupt_clear
   public :: interrupt_busy, interrupt_temporary, signal_interrupt, signal_terminate

   integer, parameter :: signal_interrupt = 2, signal_terminate = 15

   interface
      subroutine c_install(is_interactive) bind(c, name='udec_interrupt_install')
         import :: c_int
         integer(c_int), value :: is_interactive
      end subroutine c_install
      integer(c_int) function c_pending() bind(c, name='udec_interrupt_pending')
         import :: c_int
      end function c_pending
      subroutine c_clear() bind(c, name='udec_interrupt_clear')
      end subroutine c_clear
      subroutine c_busy(on) bind(c, name='udec_interrupt_busy')
         import :: c_int
         integer(c_int), value :: on
      end subroutine c_busy
      subroutine c_temporary(path) bind(c, name='udec_interrupt_temporary')
         import :: c_char
         character(kind=c_char), intent(in) :: path(*)
      end subroutine c_temporary
   end interface

contains

   !> Catch SIGINT and SIGTERM (the program's main unit, once).
   subroutine interrupt_install(interactive)
      logical, intent(in) :: interactive
      call c_install(merge(1_c_int, 0_c_int, interactive))
   end subroutine interrupt_install

   !> A signal has arrived since the last `interrupt_clear`.
   logical function interrupt_pending()
      interrupt_pending = c_pending() /= 0_c_int
   end function interrupt_pending

   !> The pending signal's number (0: none).
   integer function interrupt_signal()
      interrupt_signal = int(c_pending())
   end function interrupt_signal

   subroutine interrupt_clear()
      call c_clear()
   end subroutine interrupt_clear

   !> A command is executing (.true.) or the program waits for input.
   subroutine interrupt_busy(on)
      logical, intent(in) :: on
      call c_busy(merge(1_c_int, 0_c_int, on))
   end subroutine interrupt_busy

   !> The temporary file being written ('' when done): removed if the program
   !> is made to quit at once.
   subroutine interrupt_temporary(path)
      character(len=*), intent(in) :: path
      call c_temporary(path//c_null_char)
   end subroutine interrupt_temporary

end module core_interrupt
