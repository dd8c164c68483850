!> HELP (commands_control): the command list and one command's page, read
!> from the same registry as the parser.
program test_help
   use commands_session, only: session_t
   use testing_session, only: session_new_quiet, session_run, lines_contain
   use testing, only: check, check_equal, testing_finish
   implicit none
   type(session_t) :: s
   character(len=200), allocatable :: lines(:)

   call session_new_quiet(s)
   call session_run(s, 'HELP', lines)
   call check(size(lines) > 66, 'HELP: one line per command')
   call check(lines_contain(lines, 'PROPERTY'), 'HELP: lists PROPERTY')
   call check(lines_contain(lines, 'THIST'), 'HELP: lists the thermal commands (7.4)')
   call check(lines_contain(lines, 'HELP'), 'HELP: lists itself')

   call session_run(s, 'HEL PROP', lines)
   call check(lines_contain(lines, 'PROPERTY (shortest form PRO, manual Section 4.5)'), &
              'HELP PROP: name, shortest form, section')
   call check(lines_contain(lines, 'JKN (JKN) n [stress/length] default 0'), &
              'HELP PROP: a keyword with its shortest form, argument, unit, default')
   call check(lines_contain(lines, 'DENSITY (D) n [mass/volume]'), 'HELP PROP: DENSITY and its unit')

   ! the argument letters of the syntax line are said in words
   call session_run(s, 'HELP CYCLE', lines)
   call check(lines_contain(lines, 'syntax: CYCLE c') .and. lines_contain(lines, 'where c: an integer >= 0'), &
              'HELP CYCLE: its letter c in words')
   call session_run(s, 'HELP SOLVE', lines)
   call check(lines_contain(lines, 'where p: a real number > 0; q: an integer >= 1'), &
              'HELP SOLVE: the keywords'' letters in words')

   call session_run(s, 'HELP plot', lines)
   call check(lines_contain(lines, 'C alone is refused: it could be CABLE, CONTACTS'), &
              'HELP PLOT: the manual''s ambiguous abbreviations are named')
   call session_run(s, 'HELP PRINT', lines)
   call check(lines_contain(lines, 'CONTACTS (C) then DISPLACEMENTS (D), FORCES (F), STATE (S)'), &
              'HELP PRINT: sub-keywords with their own shortest forms')
   call session_run(s, 'HELP STRESS', lines)
   call check(.not. lines_contain(lines, 'not yet implemented'), 'HELP STRESS: implemented (issue 22)')
   call check(lines_contain(lines, 'STRESS'), 'HELP STRESS: its page')
   call check_equal(s%nerrors, 0, 'HELP: no input error so far')

   call session_run(s, 'HELP FOO', lines)
   call check_equal(s%nerrors, 1, 'HELP FOO: an unknown command is an input error')
   call check(lines_contain(lines, "HELP: unknown command 'FOO'"), 'HELP FOO: says so')
   call session_run(s, 'HELP HELP', lines)
   call check(lines_contain(lines, 'HELP (shortest form HEL, not in the manual)'), &
              'HELP HELP: its own page')
   call testing_finish()
end program test_help
