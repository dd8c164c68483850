!> core_output fmt_real / format_real: the text of reals in
!> program output. References: the Fortran ES edit descriptor (es14.5 of 1.5
!> is '   1.50000E+00'); the rule of docs/print.md (|x| < 1e-99 -> 0, clamped
!> to the largest value with two exponent digits, NaN and Infinity kept).
!> Texts are compared exactly (no tolerance: they are strings).
program test_fmt_real
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, &
                                            ieee_negative_inf
   use core_kinds, only: wp
   use core_output, only: fmt_real, format_real
   use testing, only: check, check_string, check_equal, testing_finish
   implicit none

   real(wp) :: nan, pinf, minf

   nan = ieee_value(1.0_wp, ieee_quiet_nan)
   pinf = ieee_value(1.0_wp, ieee_positive_inf)
   minf = ieee_value(1.0_wp, ieee_negative_inf)

   ! the default column: es14.5
   call check_equal(len(fmt_real(1.5_wp)), 14, 'default width 14')
   call check_string(fmt_real(1.5_wp), '   1.50000E+00', 'ordinary value as es14.5')
   call check_string(fmt_real(-2.5e-7_wp), '  -2.50000E-07', 'negative small value')
   call check_string(fmt_real(0.0_wp), '   0.00000E+00', 'zero')
   ! 3-digit exponents: dust prints as 0, huge values clamp (with the E)
   call check_string(fmt_real(1.2e-102_wp), '   0.00000E+00', '1.2e-102 prints as 0')
   call check_string(fmt_real(-1.0e-120_wp), '   0.00000E+00', '-1e-120 prints as 0 (no sign)')
   call check_string(fmt_real(1.0e-99_wp), '   1.00000E-99', '1e-99 is kept')
   call check_string(fmt_real(1.0e120_wp), '   9.99999E+99', '1e120 clamped')
   call check_string(fmt_real(-1.0e120_wp), '  -9.99999E+99', '-1e120 clamped')
   call check_string(fmt_real(huge(1.0_wp)), '   9.99999E+99', 'huge clamped')
   ! values that would round up to 1.0E+100 at the field's digits
   call check_string(fmt_real(9.999996e99_wp), '   9.99999E+99', '9.999996e99 in es14.5')
   call check_string(fmt_real(9.99995e99_wp, 12, 4), '  9.9999E+99', '9.99995e99 in es12.4')
   call check_string(fmt_real(9.9996e99_wp, 10, 3), ' 9.999E+99', '9.9996e99 in es10.3')
   call check_string(fmt_real(1.0e-120_wp, 24, 16), '  0.0000000000000000E+00', 'es24.16 dust')
   ! NaN and infinities stay recognisable
   call check(index(fmt_real(nan), 'NaN') > 0, 'NaN prints as NaN')
   call check(index(fmt_real(nan, 12, 5), 'NaN') > 0, 'NaN in es12.5 prints as NaN')
   call check(index(fmt_real(pinf), 'Infinity') > 0, '+Inf prints as Infinity')
   call check(index(fmt_real(minf), '-Inf') > 0, '-Inf prints as -Infinity')
   call check_string(fmt_real(1.0e-120_wp), '   0.00000E+00', 'dust below 1e-99 prints as 0')
   call check_string(fmt_real(-1.0e120_wp), '  -9.99999E+99', 'clamped at -9.99999E+99')
   ! the short form for messages
   call check_string(format_real(2.5_wp), '2.5', 'format_real 2.5')
   ! one character: read past its end before (issue 20; -DUDEC_SANITIZE=ON shows it)
   call check_string(format_real(5.0_wp), '5', 'format_real 5')
   call check_string(format_real(-2.0_wp), '-2', 'format_real -2')
   call check_string(format_real(0.01_wp), '0.01', 'format_real 0.01')
   call check_string(format_real(-1.5e8_wp), '-1.5E+08', 'format_real -1.5e8')
   call check_string(format_real(1.0e-120_wp), '0', 'format_real dust')
   call check_string(format_real(1.0e120_wp), '9.99999E+99', 'format_real clamped')
   call check_string(format_real(nan), 'NaN', 'format_real NaN')
   call testing_finish()
end program test_fmt_real
