!> Command and keyword tables: abbreviation matching and table consistency.
program test_grammar
   use core_error, only: error_t
   use testing, only: check, check_equal, check_string, testing_finish
   use commands_grammar, only: grammar_t, match_none, match_ambiguous
   use commands_catalog, only: grammar_build
   implicit none
   type(grammar_t) :: g
   type(error_t), allocatable :: error
   integer :: i, j, k
   character(len=:), allocatable :: abbrev
   ! Every command of manual Sections 4.5, 4.6 and 7.4.
   character(len=10), parameter :: manual_commands(66) = [character(len=10) :: &
      'ARC', 'BE', 'BLOCK', 'BOUNDARY', 'CABLE', 'CALL', 'CHANGE', 'CRACK', 'CYCLE', &
      'DAMPING', 'DELETE', 'DUMP', 'EDGE', 'END', 'FFIELD', 'FIX', 'FLUID', 'FRACTION', &
      'FREE', 'GENERATE', 'GRAVITY', 'HEADING', 'HISTORY', 'INSITU', 'ISET', 'JDELETE', &
      'JREGION', 'JSET', 'LINK', 'LOAD', 'MSCALE', 'NEW', 'PFIX', 'PFREE', 'PRINT', &
      'PROPERTY', 'QUIT', 'REINFORCE', 'RESET', 'RESTART', 'RSET', 'RETURN', 'ROUND', &
      'SAVE', 'SET', 'SPLIT', 'START', 'STOP', 'STRESS', 'STRUCTURE', 'TABLE', 'THERMAL', &
      'TUNNEL', 'UPCON', 'UPDOM', 'COPY', 'JPLOT', 'PLOT', 'WINDOW', 'INITEM', 'RUN', &
      'TADD', 'TFIX', 'TFREE', 'THAPP', 'THIST']

   call grammar_build(g, error)
   call check(.not. allocated(error), 'grammar builds')
   if (allocated(error)) call testing_finish()

   do i = 1, size(manual_commands)
      k = g%find_command(trim(manual_commands(i)))
      call check(k > 0, 'manual command known: '//trim(manual_commands(i)))
      if (k > 0) call check_string(g%commands(k)%name, trim(manual_commands(i)), &
                                   'full name resolves to itself: '//trim(manual_commands(i)))
   end do

   ! Abbreviations from the manual and the issue.
   call expect('PROP', 'PROPERTY')
   call expect('PRO', 'PROPERTY')
   call expect('PROPERTY', 'PROPERTY')
   call expect('prop', 'PROPERTY')
   call expect('CY', 'CYCLE')
   call expect('BL', 'BLOCK')
   call expect('B', 'BLOCK')
   call expect('BO', 'BOUNDARY')
   call expect('BOUND', 'BOUNDARY')
   call expect('HIST', 'HISTORY')
   call expect('GEN', 'GENERATE')
   call expect('DAMP', 'DAMPING')
   call expect('PR', 'PRINT')
   call expect('ST', 'STRESS')
   call expect('STO', 'STOP')
   call expect('STRU', 'STRUCTURE')
   call expect('HEAD', 'HEADING')
   call expect('PL', 'PLOT')
   call expect('SPL', 'SPLIT')
   call expect('FRAC', 'FRACTION')
   call check(g%find_command('ZZZ') == match_none, 'unknown command')
   call check(g%find_command('PROPERTYX') == match_none, 'longer than the name is unknown')
   call expect('C', 'CYCLE')      ! the Section 7.8 decks write `c 2000`

   ! Consistency: the minimum abbreviation of every command and keyword resolves
   ! to that same entry (no two entries claim the same abbreviation), except where
   ! the manual itself gives two keywords one letter (4.6 PLOT: Cable/Contacts,
   ! Hlstory/Hoek, Vel/Vflow; 4.5 PRINT: File/Flows): those are refused as ambiguous.
   do i = 1, g%ncommands
      associate (c => g%commands(i))
         abbrev = c%name(1:max(c%min_len, 1))
         call check_equal(g%find_command(abbrev), i, 'command minimum abbreviation '//abbrev)
         do j = 1, c%nkeywords
            abbrev = c%keywords(j)%name(1:max(c%keywords(j)%min_len, 1))
            k = c%find_keyword(abbrev)
            if ((c%name == 'PLOT' .and. any(abbrev == ['C', 'H', 'V'])) .or. &
                (c%name == 'PRINT' .and. abbrev == 'F')) then
               call check(k == match_ambiguous, c%name//' '//abbrev//' is ambiguous (manual)')
               cycle
            end if
            call check(k == j .or. (k > 0 .and. c%keywords(k)%name == c%keywords(j)%name), &
                       c%name//' keyword minimum abbreviation '//abbrev)
         end do
      end associate
   end do

   ! Keyword abbreviations used by the manual's decks.
   call expect_kw('PROPERTY', 'DENS', 'DENSITY')
   call expect_kw('PROPERTY', 'D', 'DENSITY')
   call expect_kw('PROPERTY', 'M', 'MATERIAL')
   call expect_kw('PROPERTY', 'JF', 'JFRIC')
   call expect_kw('PROPERTY', 'K', 'K')
   call expect_kw('PROPERTY', 'KN', 'KN')
   call expect_kw('BOUNDARY', 'XVIS', 'XVISC')
   call expect_kw('BOUNDARY', 'YVEL', 'YVEL')
   call expect_kw('BOUNDARY', 'STRESS', 'STRESS')
   call expect_kw('BOUNDARY', 'CO', 'COSINE')
   call expect_kw('BOUNDARY', 'COR', 'CORNER')
   call expect_kw('HISTORY', 'YVEL', 'YVEL')
   call expect_kw('HISTORY', 'N', 'NCYC')
   call expect_kw('PLOT', 'BLOCK', 'BLOCKS')
   call expect_kw('PLOT', 'VELOCITY', 'VELOCITY')
   call expect_kw('PLOT', 'HIST', 'HISTORY')
   call expect_kw('PLOT', 'M', 'MAX')
   call expect_kw('PLOT', 'MAT', 'MAT')
   call expect_kw('PRINT', 'STATE', 'STATE')
   call expect_kw('PRINT', 'STATUS', 'STATUS')
   call expect_kw('SET', 'LOG', 'LOG')
   call expect_kw('SET', '-EFF', '-EFF')
   k = g%find_command('PLOT')
   call check(g%commands(k)%find_keyword('H') == match_ambiguous .or. &
              g%commands(k)%find_keyword('H') == match_none, 'PLOT H is not silently chosen')

   call testing_finish()

contains

   subroutine expect(token, name)
      character(len=*), intent(in) :: token, name
      k = g%find_command(token)
      call check(k > 0, 'command '//token//' is known')
      if (k > 0) call check_string(g%commands(k)%name, name, 'command '//token)
   end subroutine expect

   subroutine expect_kw(command, token, name)
      character(len=*), intent(in) :: command, token, name
      integer :: c, kw
      c = g%find_command(command)
      kw = g%commands(c)%find_keyword(token)
      call check(kw > 0, command//' keyword '//token//' is known')
      if (kw > 0) call check_string(g%commands(c)%keywords(kw)%name, name, &
                                    command//' keyword '//token)
   end subroutine expect_kw

end program test_grammar
