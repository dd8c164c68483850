!> Number syntax of UDEC input (manual Section 4.1): reals may omit the decimal
!> point and may carry an exponent (1.33E7, 1e-3, 2.5D0); integers must not
!> contain a decimal point or an exponent. Values whose decimal magnitude exceeds
!> 1e300 are rejected before conversion so that no floating-point trap can fire.
module commands_numbers
   use core_kinds, only: wp
   use core_output, only: format_real   ! re-exported: the short text of a real
   implicit none
   private
   public :: looks_numeric, parse_real, parse_integer
   public :: number_ok, number_not_a_number, number_out_of_range, number_not_integer
   public :: format_real

   integer, parameter :: number_ok = 0
   integer, parameter :: number_not_a_number = 1
   integer, parameter :: number_out_of_range = 2
   integer, parameter :: number_not_integer = 3

   integer, parameter :: max_decimal_exponent = 300

contains

   !> True when a token starts like a number: a digit, or a sign or point
   !> followed by a digit (`-.5`, `+3`, `.25`).
   pure logical function looks_numeric(text)
      character(len=*), intent(in) :: text
      integer :: i
      looks_numeric = .false.
      i = 1
      if (len(text) == 0) return
      if (text(1:1) == '+' .or. text(1:1) == '-') i = 2
      if (i > len(text)) return
      if (is_digit(text(i:i))) then
         looks_numeric = .true.
      else if (text(i:i) == '.' .and. i < len(text)) then
         looks_numeric = is_digit(text(i + 1:i + 1))
      end if
   end function looks_numeric

   pure logical function is_digit(c)
      character, intent(in) :: c
      is_digit = c >= '0' .and. c <= '9'
   end function is_digit

   !> Check the lexical form of a real and estimate its decimal magnitude.
   !> `status` is number_ok, number_not_a_number or number_out_of_range.
   pure subroutine scan_real(text, status, has_point, has_exponent)
      character(len=*), intent(in) :: text
      integer, intent(out) :: status
      logical, intent(out) :: has_point, has_exponent
      integer :: i, n, int_digits, frac_digits, lead_int_zeros, lead_frac_zeros
      integer :: exp_digits, exp_value, magnitude
      logical :: exp_negative, nonzero_int, nonzero_frac
      status = number_not_a_number
      has_point = .false.
      has_exponent = .false.
      n = len(text)
      i = 1
      if (n == 0) return
      if (text(1:1) == '+' .or. text(1:1) == '-') i = 2
      call digit_run(i, int_digits, lead_int_zeros, nonzero_int)
      frac_digits = 0; lead_frac_zeros = 0; nonzero_frac = .false.
      if (i <= n) then
         if (text(i:i) == '.') then
            has_point = .true.
            i = i + 1
            call digit_run(i, frac_digits, lead_frac_zeros, nonzero_frac)
         end if
      end if
      if (int_digits + frac_digits == 0) return
      exp_value = 0
      if (i <= n) then
         select case (text(i:i))
         case ('e', 'E', 'd', 'D')
            has_exponent = .true.
            i = i + 1
            exp_negative = .false.
            if (i <= n) then
               if (text(i:i) == '+' .or. text(i:i) == '-') then
                  exp_negative = text(i:i) == '-'
                  i = i + 1
               end if
            end if
            exp_digits = 0
            do while (i <= n)
               if (.not. is_digit(text(i:i))) exit
               exp_digits = exp_digits + 1
               if (exp_value < 100000) exp_value = 10*exp_value + (ichar(text(i:i)) - ichar('0'))
               i = i + 1
            end do
            if (exp_digits == 0) return
            if (exp_negative) exp_value = -exp_value
         case default
            return
         end select
      end if
      if (i <= n) return
      status = number_ok
      if (.not. (nonzero_int .or. nonzero_frac)) return      ! zero: any exponent is fine
      if (nonzero_int) then
         magnitude = (int_digits - lead_int_zeros - 1) + exp_value
      else
         magnitude = -(lead_frac_zeros + 1) + exp_value
      end if
      if (abs(magnitude) > max_decimal_exponent) status = number_out_of_range
   contains
      !> The digits from text(k) on: how many, how many leading zeros, and
      !> whether one is not zero; k moves past them.
      pure subroutine digit_run(k, digits, lead_zeros, nonzero)
         integer, intent(inout) :: k
         integer, intent(out) :: digits, lead_zeros
         logical, intent(out) :: nonzero
         digits = 0
         lead_zeros = 0
         nonzero = .false.
         do while (k <= n)
            if (.not. is_digit(text(k:k))) exit
            digits = digits + 1
            if (text(k:k) /= '0') nonzero = .true.
            if (.not. nonzero) lead_zeros = lead_zeros + 1
            k = k + 1
         end do
      end subroutine digit_run
   end subroutine scan_real

   !> Parse a real number. `status` tells why it failed (value is 0 then).
   subroutine parse_real(text, value, status)
      character(len=*), intent(in) :: text
      real(wp), intent(out) :: value
      integer, intent(out) :: status
      logical :: has_point, has_exponent
      integer :: ios
      value = 0.0_wp
      call scan_real(text, status, has_point, has_exponent)
      if (status /= number_ok) return
      read (text, *, iostat=ios) value
      if (ios /= 0) then
         value = 0.0_wp
         status = number_not_a_number
      end if
   end subroutine parse_real

   !> Parse an integer: optional sign and digits only (no point, no exponent).
   subroutine parse_integer(text, value, status)
      character(len=*), intent(in) :: text
      integer, intent(out) :: value
      integer, intent(out) :: status
      logical :: has_point, has_exponent
      integer :: i, first, significant, ios
      value = 0
      call scan_real(text, status, has_point, has_exponent)
      if (status == number_not_a_number) return
      if (has_point .or. has_exponent) then
         status = number_not_integer
         return
      end if
      first = 1
      if (text(1:1) == '+' .or. text(1:1) == '-') first = 2
      significant = 0
      do i = first, len(text)
         if (significant > 0 .or. text(i:i) /= '0') significant = significant + 1
      end do
      if (significant > 9) then
         status = number_out_of_range
         return
      end if
      read (text, *, iostat=ios) value
      if (ios /= 0) then
         value = 0
         status = number_not_a_number
      else
         status = number_ok
      end if
   end subroutine parse_integer

end module commands_numbers
