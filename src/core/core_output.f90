!> Where program text goes: the screen, the batch OUT file, the UDEC.LOG file
!> and PRINT FILE redirection. An `output_t` is passed explicitly to whatever
!> writes; it owns no model state.
module core_output
   use, intrinsic :: iso_fortran_env, only: output_unit
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use core_kinds, only: wp, i8
   implicit none
   private
   public :: output_t, max_sinks, fmt_real, format_real, itoa

   !> An integer as its shortest text (i0), for messages and legends.
   interface itoa
      module procedure itoa_default, itoa_i8
   end interface itoa

   integer, parameter :: max_sinks = 4

   !> A set of open units that every line is written to.
   type :: output_t
      integer :: nsink = 0
      integer :: unit(max_sinks) = -1
      logical :: screen = .true.     !< also write to standard output
      !> detail notes wanted (SET LOG ON): e.g. one note per refused cut
      logical :: detail = .false.
      !> standard output is a terminal (set by the program): CYCLE, SOLVE and
      !> RUN show one progress line there instead of their rows (`row`)
      logical :: tty = .false.
   contains
      procedure :: line => output_line
      procedure :: row => output_row
      procedure :: add_unit => output_add_unit
      procedure :: remove_unit => output_remove_unit
   end type output_t

contains

   !> `x` as the printed tables may show it with `digits` decimals after the
   !> point. An `esW.D` edit descriptor writes exponents beyond +-99 without
   !> the letter E (1.23456-102), which no reader takes for a number;
   !> magnitudes below 1e-99 (the numerical dust of a wave front, physically
   !> zero) become 0 and finite ones beyond the largest value that does not
   !> round up to 1e100 are clamped to it. NaN and infinities pass through.
   elemental real(wp) function clamped(x, digits) result(y)
      real(wp), intent(in) :: x
      integer, intent(in) :: digits
      real(wp) :: big
      y = x
      ! NaN and infinities unchanged (no comparison on a NaN: FP traps)
      if (.not. ieee_is_finite(x)) return
      big = (10.0_wp - 10.0_wp**(-digits))*1.0e99_wp
      if (abs(x) < 1.0e-99_wp) then
         y = 0.0_wp
      else if (abs(x) > big) then
         y = sign(big, x)
      end if
   end function clamped

   !> The text of a real as an `esW.De2` field (default es14.5, the column of
   !> the printed tables), always readable: the value goes through `clamped`
   !> for `d` digits, so the exponent has two digits and its E (0 for
   !> |x| < 1e-99, +-9.99..9E+99 at most); NaN prints as NaN and an infinity
   !> as Infinity, right-aligned. Every real in program text is written
   !> through this function or `format_real`.
   pure function fmt_real(x, w, d) result(text)
      real(wp), intent(in) :: x
      integer, intent(in), optional :: w, d
      character(len=:), allocatable :: text
      character(len=24) :: form
      integer :: ww, dd
      ww = 14
      dd = 5
      if (present(w)) ww = w
      if (present(d)) dd = d
      allocate (character(len=ww) :: text)
      write (form, '(a,i0,a,i0,a)') '(es', ww, '.', dd, 'e2)'
      write (text, form) clamped(x, dd)
   end function fmt_real

   !> Short text of a real for messages: fixed notation with up to six
   !> decimals for 1e-3 <= |v| < 1e7, else six significant digits in
   !> exponent form (through `fmt_real`: two exponent digits, 0 below 1e-99
   !> in magnitude); trailing zeros dropped (2.5, 0.01, -1.5E+08, NaN).
   pure function format_real(v) result(text)
      real(wp), intent(in) :: v
      character(len=:), allocatable :: text
      character(len=40) :: buf
      integer :: e, i
      if (.not. ieee_is_finite(v)) then
         text = trim(adjustl(fmt_real(v)))
      else if (abs(v) < 1.0e-99_wp) then
         text = '0'
      else if (abs(v) >= 1.0e-3_wp .and. abs(v) < 1.0e7_wp) then
         write (buf, '(f0.6)') v
         buf = adjustl(buf)
         i = len_trim(buf)
         do while (buf(i:i) == '0')
            i = i - 1
         end do
         if (buf(i:i) == '.') i = i - 1
         text = buf(1:i)
         if (text(1:1) == '.') text = '0'//text
         ! '5' has no second character (AddressSanitizer: a read past the
         ! end of a one-character text, issue 20)
         if (len(text) >= 2) then
            if (text(1:2) == '-.') text = '-0'//text(2:)
         end if
      else
         buf = adjustl(fmt_real(v, 16, 5))
         e = index(buf, 'E')
         i = e - 1
         do while (buf(i:i) == '0')
            i = i - 1
         end do
         if (buf(i:i) == '.') i = i - 1
         text = buf(1:i)//trim(buf(e:))
      end if
   end function format_real

   !> Write one line of text to every sink.
   subroutine output_line(this, text)
      class(output_t), intent(in) :: this
      character(len=*), intent(in) :: text
      call output_emit(this, text, this%screen)
   end subroutine output_line

   !> A progress row of CYCLE or RUN: as `line`, except that a terminal
   !> (`tty`) gets the progress line (core_progress) instead; files and
   !> pipes get the rows exactly as the manual prints them.
   subroutine output_row(this, text)
      class(output_t), intent(in) :: this
      character(len=*), intent(in) :: text
      call output_emit(this, text, this%screen .and. .not. this%tty)
   end subroutine output_row

   !> Write `text` to every sink, and to the screen when `screen`.
   subroutine output_emit(this, text, screen)
      class(output_t), intent(in) :: this
      character(len=*), intent(in) :: text
      logical, intent(in) :: screen
      integer :: i
      if (screen) then
         write (output_unit, '(a)') trim(text)
         flush (output_unit)
      end if
      do i = 1, this%nsink
         write (this%unit(i), '(a)') trim(text)
      end do
   end subroutine output_emit

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

   pure function itoa_default(i) result(text)
      integer, intent(in) :: i
      character(len=:), allocatable :: text
      character(len=12) :: buf
      write (buf, '(i0)') i
      text = trim(buf)
   end function itoa_default

   pure function itoa_i8(i) result(text)
      integer(i8), intent(in) :: i
      character(len=:), allocatable :: text
      character(len=24) :: buf
      write (buf, '(i0)') i
      text = trim(buf)
   end function itoa_i8

end module core_output
