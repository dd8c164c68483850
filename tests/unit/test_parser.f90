!> Parsing commands against the tables: positional arguments, keywords, ranges,
!> loose numbers, error messages; and logical-line assembly with '&' and '+'.
program test_parser
   use core_kinds, only: wp
   use core_error, only: error_t
   use core_output, only: output_t
   use core_range, only: range_box, range_region, range_annulus, range_all
   use testing, only: check, check_equal, check_string, check_close, testing_finish
   use commands_tokens, only: token_t, tokenize, strip_comment
   use commands_grammar, only: grammar_t
   use commands_catalog, only: grammar_build
   use commands_parser, only: parsed_t, parse_command, item_loose
   use commands_source, only: source_t, source_open_file, source_read_logical, source_close
   implicit none
   type(grammar_t) :: g
   type(parsed_t) :: p
   type(error_t), allocatable :: error
   integer :: k
   !> quoted file names and the names they give
   character(len=32), parameter :: quoted(3) = [character(len=32) :: 'SAVE "q.sav"', &
                                                "RESTART 'my run.sav'", 'PRINT FILE "out 1.txt" MAX']
   character(len=16), parameter :: unquoted(3) = [character(len=16) :: 'q.sav', 'my run.sav', &
                                                  'out 1.txt']

   call grammar_build(g, error)

   ! Tutorial commands
   call parse_ok('PROP JMAT=1 JKN=1.33E7 JKS=1.33E7 JFRIC=0.35')
   call check_string(p%name, 'PROPERTY', 'PROP is PROPERTY')
   k = p%find('JKN')
   call check(k > 0, 'JKN present')
   if (k > 0) call check_close(p%real_at(k, 1), 1.33e7_wp, 1.0e-15_wp, 'JKN value')
   k = p%find('JMATERIAL')
   call check(k > 0, 'JMAT present')
   if (k > 0) call check_equal(p%int_at(k, 1), 1, 'JMAT value')

   call parse_ok('CYCLE 100')
   call check_equal(p%int_at(1, 1), 100, 'CYCLE count')
   call parse_ok('HIST YVEL(10,20) TYPE 1')
   k = p%find('YVEL')
   call check_close(p%real_at(k, 2), 20.0_wp, 0.0_wp, 'HIST YVEL y')

   ! count_of: how many items are one of several keywords, and the last of them
   call parse_ok('THAPP 0 1 0 1 CONV 10 20 FLUX 1 2')
   call check_equal(p%count_of([character(len=10) :: 'CONVECTION', 'FLUX', 'RADIATION', &
                                'SOURCE'], k), 2, 'THAPP: two of its four keywords')
   call check_equal(k, p%find('FLUX'), 'the last of them is FLUX')
   call parse_ok('THAPP 0 1 0 1 RAD 10 20')
   call check_equal(p%count_of([character(len=10) :: 'CONVECTION', 'FLUX'], k), 0, &
                    'THAPP RAD: none of CONVECTION, FLUX')
   call check_equal(k, 0, 'no last item when none is given')

   ! BLOCK: corner pairs are loose numbers, keywords may come first
   call parse_ok('BLOCK MAT 2 CONS 1 (0,0) (0,20) (20,20) (20,0)')
   call check_equal(p%items(p%nitems)%keyword, item_loose, 'corner list is the loose item')
   call check_equal(p%items(p%nitems)%count, 8, 'eight corner numbers')
   call parse_err('BLOCK (0,0) (0,20) (20', 'line ended')

   ! Ranges: box (inclusive, small tolerance), REG, ANN, equal limits accepted, reversed swapped
   call parse_ok('FIX 0,20 0,5')
   call check(p%has_range .and. p%range%kind == range_box, 'FIX box range')
   call check(p%range%contains_point(10.0_wp, 2.0_wp), 'centroid inside range')
   call check(p%range%contains_point(10.0_wp, 5.0_wp), 'range includes its edge yu')
   call check(p%range%contains_point(20.0_wp + 1.0e-6_wp, 0.0_wp), 'edge tolerance 1e-6 x 20')
   call check(.not. p%range%contains_point(10.0_wp, 5.001_wp), 'range excludes points beyond yu')
   call parse_ok('CHANGE REG 0,0 0,10 10,10 10,0 JMAT 2')
   call check(p%range%kind == range_region, 'REG range')
   call check(p%range%contains_point(5.0_wp, 5.0_wp), 'point inside region')
   call check(.not. p%range%contains_point(15.0_wp, 5.0_wp), 'point outside region')
   call parse_ok('PRINT ANN 0 0 1 2 BLOCK')
   call check(p%range%kind == range_annulus, 'ANN range')
   call check(p%range%contains_point(1.5_wp, 0.0_wp), 'point inside annulus')
   call check(.not. p%range%contains_point(0.5_wp, 0.0_wp), 'point in the hole')
   call parse_ok('BOUND 0,12 10,10 XVEL 0')
   call check(p%range%contains_point(12.0_wp, 10.0_wp), 'equal y limits: the line y = 10, end included')
   call check(.not. p%range%contains_point(6.0_wp, 9.99_wp), 'equal y limits: nothing off the line')
   ! a range after the keywords (later UDECs' order) is the same range
   call parse_ok('BOUND STRESS 0 0 -1e6 -1,31 39.9,40.1')
   call check(p%has_range .and. p%range%kind == range_box, 'BOUND range after STRESS')
   call check(p%range%contains_point(10.0_wp, 40.0_wp), 'trailing range holds the top')
   call check(.not. p%range%contains_point(10.0_wp, 0.0_wp), 'trailing range leaves the base')
   call check_close(p%real_at(p%find('STRESS'), 3), -1.0e6_wp, 0.0_wp, 'STRESS keeps its 3 values')
   call parse_ok('BOUND XVEL 0 ANN 5 5 1 2')
   call check(p%range%kind == range_annulus, 'ANN range after XVEL')
   call parse_err('BOUND 0,1 0,1 XVEL 0 2,3 2,3', 'unexpected number')
   ! the word RANGE before a range (later UDECs' habit; an extension) is dropped
   call parse_ok('BOUND YVEL 0 RANGE 0,60 -0.1,0.1')
   call check(p%has_range .and. p%range%kind == range_box, 'RANGE word before a box range')
   call check(p%range%contains_point(30.0_wp, 0.0_wp) .and. &
              .not. p%range%contains_point(30.0_wp, 1.0_wp), 'RANGE box holds the base only')
   call parse_ok('FIX range 0,20 0,5')
   call check(p%has_range .and. p%range%xu == 20.0_wp .and. p%range%yu == 5.0_wp, 'FIX RANGE box')
   call parse_ok('DELETE RANGE ANN 5 5 0 2')
   call check(p%range%kind == range_annulus, 'RANGE word before ANN')
   call parse_err('FIX RANGE', 'after RANGE (line ended)')
   call parse_err('BOUND XVEL 0 RA 0,1 0,1', "unknown keyword 'RA'")
   ! reversed limits are refused naming the pair (manual Section 4.1: xl < x < xu)
   call parse_err('FIX 20 0 5 0', 'range 20 0 5 0: xl > xu')
   call parse_err('FIX 0 20 5 0', 'lower limit first: give 0 5')
   call parse_ok('FIX 0 20 5 5')
   call check(p%range%yl == 5.0_wp .and. p%range%yu == 5.0_wp, 'equal limits kept (a line)')
   call parse_ok('CHANGE MAT 2')
   call check(.not. p%has_range .and. p%range%kind == range_all, 'range is optional')
   call parse_err('FIX 0 1', 'range needs more numbers')
   call parse_err('FIX', 'line ended')
   ! a keyword given too many values: the numbers left over start a trailing
   ! range, which runs short; the message names them and whose values they follow
   call parse_err('INSITU STRESS 0 0 0 YGRAD 0 0 0 0 0 0', "left after YGRAD's values ('0 0 0')")
   call parse_err('BOUND YVEL 0 0 1 0', "left after YVEL's values ('0 1 0')")
   ! a long keyword list cut to the token's first letter says so
   call parse_err('PROPERTY JMAT=1 BOGUS=3', 'PROPERTY (those starting with B: BULK; HELP PROPERTY lists all)')

   ! Optional groups and repeats
   call parse_ok('DAMP AUTO')
   call check_equal(p%items(p%find('AUTO'))%count, 0, 'DAMP AUTO with defaults')
   call parse_ok('DAMP AUTO 0.5 0.99 1.05')
   call check_equal(p%items(p%find('AUTO'))%count, 3, 'DAMP AUTO with three values')
   call parse_ok('DAMP 0.05 10 MASS')
   call check_equal(p%items(1)%count, 2, 'Rayleigh damping values')
   call parse_ok('PLOT HISTORY 1 2 3')
   call check_equal(p%items(p%find('HISTORY'))%count, 3, 'PLOT HIST list')
   call parse_err('PLOT HISTORY', 'line ended')
   call parse_ok('JSET 90.0,0 5.0,0 0.0,0 0.2,0 (0.0,0.0, 0.0)')
   call check_equal(p%items(1)%count, 11, 'JSET with origin and angle deviation')
   call parse_ok('JSET 90.0,0 5.0,0 0.0,0 0.2,0')
   call check_equal(p%items(1)%count, 8, 'JSET without optional values')

   ! File names keep / and = characters
   call parse_ok('SAVE runs/slope=1.sav')
   call check_string(p%text_at(1, 1), 'runs/slope=1.sav', 'file name with / and =')
   ! an absolute path keeps its leading / (a delimiter elsewhere on the line)
   call parse_ok('SAVE /tmp/runs/slope.sav')
   call check_string(p%text_at(1, 1), '/tmp/runs/slope.sav', 'absolute file name')
   call parse_ok('COPY //server/plots/a.ps')
   call check_string(p%text_at(1, 1), '//server/plots/a.ps', 'file name starting with //')
   call parse_ok('PRINT FILE /tmp/out.txt MAX')
   call check_string(p%text_at(p%find('FILE'), 1), '/tmp/out.txt', 'PRINT FILE absolute name')
   ! DELETE's range after its keyword, as the other range commands take it
   call parse_ok('DELETE AREA 0.5 0 10 0 10')
   call check(p%has_range .and. p%items(p%find('AREA'))%count == 1, 'DELETE AREA a, then the range')
   ! a name in quotes is the text between them (it was the file '"q.sav"')
   do k = 1, 3
      call parse_ok(trim(quoted(k)))
      call check_string(p%text_at(max(1, p%find('FILE')), 1), trim(unquoted(k)), trim(quoted(k)))
   end do
   call check(p%find('MAXIMA') > 0, 'PRINT FILE quoted name: MAX follows')
   call parse_err('SAVE "q.sav', 'between quotes')
   call parse_err('SAVE ""', 'between quotes')
   call parse_ok('RESTART')
   call check_equal(p%items(1)%count, 0, 'RESTART default file')
   call parse_ok('HIST WRITE 1 hist1.txt')
   k = p%find('WRITE')
   call check_string(p%text_at(k, 2), 'hist1.txt', 'HIST WRITE file')

   ! Errors name command, token and expectation
   call parse_err('PROP MAT=1 DENS=-2000', "PROPERTY DENSITY: expected a real number >= 0, got '-2000'")
   call parse_err('CYCLE 10.0', "no decimal point")
   call parse_err('CYCLE ten', "expected an integer >= 0, got 'ten'")
   call parse_err('PROP MAT 1 WIBBLE 3', "PROPERTY: unknown keyword 'WIBBLE'")
   call parse_err('CYCLE 10 20', "unexpected number '20'")
   ! a command that takes a range says so (a new user's DELETE RANG ..: the
   ! word RANGE itself is read as the start of the range, above)
   call parse_err('DELETE RANG 0 1 0 1', "DELETE: AREA, BLOCK, or a range (xl xu yl yu")
   call parse_err('FROBNICATE 1', "unknown command 'FROBNICATE'")
   call parse_err('PROP MAT 1 DENS 1e999', 'out of range')
   call parse_err('ROUND 0', 'expected a real number > 0')
   call parse_err('PROP MAT 0 DENS 1', 'expected an integer >= 1')
   ! manual 4.6: Hlstory and Hoek both abbreviate to H
   call parse_err('PLOT H 1', "ambiguous keyword 'H' (could be HISTORY, HOEK; type more letters)")

   ! a number after a keyword that takes none names the keyword as read and
   ! what was meant (BOUNDARY: YV is YVISC, YVEL has no shorter form; PLOT's
   ! WINDOW draws the frame, the WINDOW command sets it)
   call parse_err('BOUND 0 10 -.1 .1 yv 0', "BOUNDARY: unexpected number '0' after YVISC " &
                  //"(read from 'yv'), which takes no value; did you mean YVEL " &
                  //"(shortest form YVEL)?")
   call parse_err('PLOT WINDOW 0 5 0 5', "PLOT: unexpected number '0' after WINDOW, which " &
                  //"takes no value; WINDOW with numbers is the command WINDOW, given on a line " &
                  //"of its own (HELP WINDOW)")
   call parse_err('BOUND STRESS 1 2 3 0 1 0 1 5', "unexpected number '5' after STRESS, which " &
                  //"takes no more values (expected")

   ! numbers as 1989 decks wrote them (manual Section 4.1): FORTRAN D
   ! exponents, a bare point, signed exponents; tabs and a trailing comma
   call parse_ok('PROP MAT=1 DENS=1D3 K=1.E6'//char(9)//'G=1e+06, JKN=5. JKS=.5 JFRIC=.5,')
   call check_close(p%real_at(p%find('DENSITY'), 1), 1.0e3_wp, 0.0_wp, '1D3 is 1000')
   call check_close(p%real_at(p%find('K'), 1), 1.0e6_wp, 0.0_wp, '1.E6')
   call check_close(p%real_at(p%find('G'), 1), 1.0e6_wp, 0.0_wp, 'tab, then 1e+06')
   call check_close(p%real_at(p%find('JKN'), 1), 5.0_wp, 0.0_wp, '5. is five')
   call check_close(p%real_at(p%find('JKS'), 1), 0.5_wp, 0.0_wp, '.5')
   call parse_ok('GRAV 0. , -9.81D0 ,')
   call check_close(p%real_at(1, 2), -9.81_wp, 0.0_wp, 'GRAV y with D0 and a trailing comma')

   call test_continuation()
   call testing_finish()

contains

   subroutine parse_line(line)
      character(len=*), intent(in) :: line
      type(token_t), allocatable :: tok(:)
      integer :: n
      character(len=:), allocatable :: code
      code = strip_comment(line)
      call tokenize(code, tok, n)
      call parse_command(g, code, tok, n, p, error)
   end subroutine parse_line

   subroutine parse_ok(line)
      character(len=*), intent(in) :: line
      call parse_line(line)
      call check(.not. allocated(error), 'parses: '//line)
      if (allocated(error)) write (*, '(a)') '   '//error%message
   end subroutine parse_ok

   subroutine parse_err(line, fragment)
      character(len=*), intent(in) :: line, fragment
      call parse_line(line)
      call check(allocated(error), 'rejected: '//line)
      if (allocated(error)) then
         call check(index(error%message, fragment) > 0, 'message of "'//line//'" contains "' &
                    //fragment//'": '//error%message)
      end if
   end subroutine parse_err

   !> '&' at the end of a line and '+' at the start of the next both continue.
   subroutine test_continuation()
      type(source_t) :: src
      type(output_t) :: quiet
      character(len=:), allocatable :: code
      integer :: u, first
      logical :: ok, eof, too_long
      open (newunit=u, file='test_parser_continuation.dat', status='replace', action='write')
      write (u, '(a)') 'BLOCK 0,0 0,20 &   * comment after the ampersand'
      write (u, '(a)') '      20,20 20,0'
      write (u, '(a)') 'PROP MAT=1'
      write (u, '(a)') '+ DENS=2000'
      write (u, '(a)') '  + JKN=1e7'
      write (u, '(a)') 'CYCLE 10'
      close (u)
      quiet%screen = .false.
      call source_open_file(src, 'test_parser_continuation.dat', ok)
      call check(ok, 'continuation file opens')
      call source_read_logical(src, quiet, '', code, first, eof, too_long)
      call parse_ok(code)
      call check_equal(p%items(p%nitems)%count, 8, '& joins the BLOCK corner list')
      call check_equal(first, 1, 'logical line 1 starts at line 1')
      call source_read_logical(src, quiet, '', code, first, eof, too_long)
      call parse_ok(code)
      call check(p%find('DENSITY') > 0 .and. p%find('JKN') > 0, '+ lines join PROP')
      call check_equal(first, 3, 'PROP starts at line 3')
      call source_read_logical(src, quiet, '', code, first, eof, too_long)
      call parse_ok(code)
      call check_string(p%name, 'CYCLE', 'line after + continuation')
      call check_equal(first, 6, 'CYCLE is line 6')
      call source_read_logical(src, quiet, '', code, first, eof, too_long)
      call check(eof, 'end of file')
      call source_close(src)
      open (newunit=u, file='test_parser_continuation.dat', status='old')
      close (u, status='delete')
   end subroutine test_continuation

end program test_parser
