!> One progress line, updated in place on a terminal (issue 24): cycles done
!> of the total, percent, cycles per second, time left and a caller's note
!> (the unbalanced-force ratio), at most four updates a second, written with
!> a carriage return and erased when the loop ends. Only when the output's
!> `tty` is set (standard output is a terminal); batch output keeps the rows.
module core_progress
   use, intrinsic :: iso_fortran_env, only: output_unit
   use, intrinsic :: iso_c_binding, only: c_int
   use core_kinds, only: wp, i8
   use core_output, only: output_t, fmt_real, format_real, itoa
   implicit none
   private
   public :: progress_t, stdout_is_terminal

   interface
      integer(c_int) function c_isatty() bind(c, name='udec_stdout_isatty')
         import :: c_int
      end function c_isatty
   end interface

   type :: progress_t
      logical :: active = .false.
      logical :: shown = .false.
      integer(i8) :: total = 0, t0 = 0, tlast = 0, rate = 1
      character(len=16) :: what = 'cycle'
   contains
      procedure :: start => progress_start
      procedure :: due => progress_due
      procedure :: show => progress_show
      procedure :: finish => progress_finish
   end type progress_t

contains

   !> Standard output is a terminal.
   logical function stdout_is_terminal()
      stdout_is_terminal = c_isatty() /= 0_c_int
   end function stdout_is_terminal

   !> A loop of `total` steps begins (`what`: 'cycle', 'thermal step').
   subroutine progress_start(this, out, total, what)
      class(progress_t), intent(inout) :: this
      type(output_t), intent(in) :: out
      integer(i8), intent(in) :: total
      character(len=*), intent(in) :: what
      this%active = out%tty .and. out%screen .and. total > 0
      this%shown = .false.
      this%total = total
      this%what = what
      call system_clock(this%t0, this%rate)
      this%rate = max(this%rate, 1_i8)
      this%tlast = this%t0
   end subroutine progress_start

   !> A quarter of a second has passed since the last update (or the loop
   !> is at its end): the caller computes its note and calls `show`.
   logical function progress_due(this, done)
      class(progress_t), intent(in) :: this
      integer(i8), intent(in) :: done
      integer(i8) :: t
      progress_due = .false.
      if (.not. this%active) return
      call system_clock(t)
      progress_due = 4_i8*(t - this%tlast) >= this%rate .or. done >= this%total
   end function progress_due

   !> Rewrite the line: `done` of the total, percent, rate, time left, note.
   subroutine progress_show(this, done, note)
      class(progress_t), intent(inout) :: this
      integer(i8), intent(in) :: done
      character(len=*), intent(in) :: note
      integer(i8) :: t
      real(wp) :: elapsed, per_second, left
      character(len=:), allocatable :: text
      if (.not. this%active) return
      call system_clock(t)
      this%tlast = t
      elapsed = real(t - this%t0, wp)/real(this%rate, wp)
      per_second = real(done, wp)/max(elapsed, 1.0e-9_wp)
      text = trim(this%what)//' '//itoa(done)//' of '//itoa(this%total)//' ('// &
             itoa(int(100.0_wp*real(done, wp)/real(this%total, wp)))//' %), '// &
             trim(adjustl(fmt_real(per_second, 10, 3)))//'/s'
      if (done > 0) then
         left = real(this%total - done, wp)/max(per_second, 1.0e-9_wp)
         text = text//', '//format_real(real(nint(left*10.0_wp), wp)/10.0_wp)//' s left'
      end if
      if (len_trim(note) > 0) text = text//', '//trim(note)
      write (output_unit, '(a)', advance='no') achar(13)//text//achar(27)//'[K'
      flush (output_unit)
      this%shown = .true.
   end subroutine progress_show

   !> The loop has ended, or a note is about to be written: erase the line
   !> so the next output starts clean (a later `show` draws it again).
   subroutine progress_finish(this)
      class(progress_t), intent(inout) :: this
      if (this%shown) then
         write (output_unit, '(a)', advance='no') achar(13)//achar(27)//'[K'
         flush (output_unit)
      end if
      this%shown = .false.
   end subroutine progress_finish

end module core_progress
