!> Tokenizer and number syntax (manual Section 4.1).
program test_tokens
   use core_kinds, only: wp
   use testing, only: check, check_equal, check_string, check_close, testing_finish
   use commands_tokens, only: token_t, tokenize, strip_comment, to_upper
   use commands_numbers, only: looks_numeric, parse_real, parse_integer, number_ok, &
                               number_not_a_number, number_out_of_range, number_not_integer
   implicit none
   type(token_t), allocatable :: tok(:)
   integer :: n, status, iv
   real(wp) :: rv

   ! Delimiters: blanks, tabs and ( ) , / =
   call tokenize('BLOCK      (0,0) (0,20) (20,20) (20,0)', tok, n)
   call check_equal(n, 9, 'tutorial BLOCK line has 9 tokens')
   call check_string(tok(1)%text, 'BLOCK', 'first token')
   call check_string(tok(2)%text, '0', 'parenthesised x')
   call check_string(tok(9)%text, '0', 'last y')
   call check_equal(tok(1)%first, 1, 'column of first token')
   call tokenize('PROP MAT=1 DENS=2000/JKN'//char(9)//'=1.33E7', tok, n)
   call check_equal(n, 7, 'equals, slash and tab are delimiters')
   call check_string(tok(6)%text, 'JKN', 'token after slash')
   call check_string(tok(7)%text, '1.33E7', 'exponent kept in one token')
   call tokenize('   ', tok, n)
   call check_equal(n, 0, 'blank line has no tokens')
   call tokenize('BOUND -1,,1 -.1,2.1', tok, n)
   call check_equal(n, 5, 'empty fields between delimiters are skipped')
   ! many tokens force growth of the token array
   call tokenize(repeat('1 ', 500), tok, n)
   call check_equal(n, 500, '500 tokens')

   ! Comments: everything after '*' is ignored
   call check_string(strip_comment('CYCLE 100 * run it'), 'CYCLE 100 ', 'trailing comment')
   call check_string(strip_comment('* whole line'), '', 'comment line')
   call check_string(strip_comment('no comment'), 'no comment', 'no comment')
   call check_string(strip_comment('CYCLE 100 ; run it'), 'CYCLE 100 ', 'trailing ; comment')
   call check_string(strip_comment('GRAV 0 -9.81 ; g * 1'), 'GRAV 0 -9.81 ', '; before *')
   call check_string(to_upper('Prop jkn=1e3'), 'PROP JKN=1E3', 'to_upper')

   ! Numeric look
   call check(looks_numeric('12'), '12 looks numeric')
   call check(looks_numeric('-.5'), '-.5 looks numeric')
   call check(looks_numeric('+3'), '+3 looks numeric')
   call check(looks_numeric('.25'), '.25 looks numeric')
   call check(.not. looks_numeric('-EFF'), '-EFF is a word')
   call check(.not. looks_numeric('.'), 'a lone point is not a number')
   call check(.not. looks_numeric('E5'), 'E5 is a word')

   ! Reals: decimal point optional, exponents accepted
   call parse_real('1.33E7', rv, status)
   call check(status == number_ok, '1.33E7 parses')
   call check_close(rv, 1.33e7_wp, 1.0e-15_wp, '1.33E7 value')
   call parse_real('1e-3', rv, status)
   call check_close(rv, 1.0e-3_wp, 1.0e-15_wp, '1e-3 value')
   call parse_real('2000', rv, status)
   call check_close(rv, 2000.0_wp, 0.0_wp, 'real without a point')
   call parse_real('-.1', rv, status)
   call check_close(rv, -0.1_wp, 1.0e-15_wp, '-.1 value')
   call parse_real('2.5D0', rv, status)
   call check_close(rv, 2.5_wp, 0.0_wp, 'Fortran D exponent')
   call parse_real('1.2.3', rv, status)
   call check(status == number_not_a_number, '1.2.3 malformed')
   call parse_real('1e', rv, status)
   call check(status == number_not_a_number, 'exponent without digits')
   call parse_real('12abc', rv, status)
   call check(status == number_not_a_number, 'trailing letters')
   call parse_real('1e999', rv, status)
   call check(status == number_out_of_range, 'huge exponent is out of range')
   call parse_real('1e-999', rv, status)
   call check(status == number_out_of_range, 'tiny exponent is out of range')
   call parse_real('0e99999', rv, status)
   call check(status == number_ok .and. rv == 0.0_wp, 'zero with any exponent')
   call parse_real('1'//repeat('0', 400), rv, status)
   call check(status == number_out_of_range, '400-digit integer part out of range')
   call parse_real('0.'//repeat('0', 100)//'1', rv, status)
   call check(status == number_ok, 'many leading fractional zeros are fine')
   call check_close(rv, 1.0e-101_wp, 1.0e-12_wp, 'leading zeros value')

   ! Integers: no decimal point, no exponent
   call parse_integer('100', iv, status)
   call check(status == number_ok .and. iv == 100, 'integer 100')
   call parse_integer('-7', iv, status)
   call check(status == number_ok .and. iv == -7, 'integer -7')
   call parse_integer('100.', iv, status)
   call check(status == number_not_integer, 'decimal point rejected in an integer')
   call parse_integer('1e3', iv, status)
   call check(status == number_not_integer, 'exponent rejected in an integer')
   call parse_integer('12345678901', iv, status)
   call check(status == number_out_of_range, 'integer overflow rejected')
   call parse_integer('x1', iv, status)
   call check(status == number_not_a_number, 'word is not an integer')
   call parse_integer('000000000000012', iv, status)
   call check(status == number_ok .and. iv == 12, 'leading zeros in an integer')

   call testing_finish()
end program test_tokens
