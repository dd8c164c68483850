!> Every real that PRINT (and the CYCLE lines) write is readable as a number.
!> An `esW.D` edit descriptor drops the letter E of a 3-digit exponent
!> (1e-120 -> `1.00000-120`), which neither a person nor float() reads; the
!> tables print magnitudes below 1e-99 as 0 and clamp beyond 9.99999e99
!> (core_output fmt_real). Two small models are built through the command
!> interpreter, values of +-1e-120 and +-1e120 are put into the printed
!> quantities, and every numeric token of every table must parse as a real.
program test_print_tiny
   use core_kinds, only: wp, ip
   use core_error, only: error_t
   use commands_session, only: session_t, session_init
   use testing_session, only: session_run, lines_contain
   use testing, only: check, check_equal, testing_finish
   implicit none

   real(wp), parameter :: tiny_v = 1.0e-120_wp   !< numerical dust: prints as 0
   real(wp), parameter :: huge_v = 1.0e120_wp    !< beyond 1e100: clamped
   character(len=*), parameter :: clamped = '9.99999E+99'

   type(session_t) :: session
   character(len=200), allocatable :: lines(:)

   call test_rigid_tables()
   call test_zone_tables()
   call test_cycle_lines()
   call testing_finish()

contains

   subroutine run(text)
      character(len=*), intent(in) :: text
      call session_run(session, text, lines)
   end subroutine run

   subroutine fresh()
      type(error_t), allocatable :: error
      call session_init(session, error)
      call check(.not. allocated(error), 'session starts')
   end subroutine fresh

   !> A token is a number when it starts with a digit, or with a sign or a
   !> point followed by a digit or a point.
   pure logical function numeric_start(tok)
      character(len=*), intent(in) :: tok
      numeric_start = .false.
      if (len(tok) == 0) return
      if (index('0123456789', tok(1:1)) > 0) then
         numeric_start = .true.
      else if (len(tok) >= 2 .and. index('+-.', tok(1:1)) > 0) then
         numeric_start = index('0123456789.', tok(2:2)) > 0
      end if
   end function numeric_start

   !> The syntax every reader accepts (Python float, C strtod, Fortran):
   !> [sign] digits [. digits] [E|e [sign] digits], at least one mantissa
   !> digit. `1.22047-102` (no E) is rejected.
   pure logical function is_real_text(tok) result(ok)
      character(len=*), intent(in) :: tok
      integer :: i, nmant, nexp
      ok = .false.
      i = 1
      nmant = 0
      if (index('+-', tok(i:i)) > 0) i = i + 1
      do while (i <= len(tok))
         if (index('0123456789', tok(i:i)) == 0) exit
         nmant = nmant + 1; i = i + 1
      end do
      if (i <= len(tok)) then
         if (tok(i:i) == '.') then
            i = i + 1
            do while (i <= len(tok))
               if (index('0123456789', tok(i:i)) == 0) exit
               nmant = nmant + 1; i = i + 1
            end do
         end if
      end if
      if (nmant == 0) return
      if (i > len(tok)) then
         ok = .true.
         return
      end if
      if (index('Ee', tok(i:i)) == 0) return
      i = i + 1
      if (i <= len(tok)) then
         if (index('+-', tok(i:i)) > 0) i = i + 1
      end if
      nexp = 0
      do while (i <= len(tok))
         if (index('0123456789', tok(i:i)) == 0) return
         nexp = nexp + 1; i = i + 1
      end do
      ok = nexp > 0
   end function is_real_text

   !> The first numeric token of `line` that is not a readable real ('' if none).
   function bad_token(line) result(bad)
      character(len=*), intent(in) :: line
      character(len=:), allocatable :: bad
      character(len=*), parameter :: sep = ' ,()=:;<>/'
      integer :: i, j
      bad = ''
      i = 1
      do while (i <= len_trim(line))
         if (index(sep, line(i:i)) > 0) then
            i = i + 1
            cycle
         end if
         j = i
         do while (j < len_trim(line))
            if (index(sep, line(j + 1:j + 1)) > 0) exit
            j = j + 1
         end do
         if (numeric_start(line(i:j))) then
            if (.not. is_real_text(line(i:j))) then
               bad = line(i:j)
               return
            end if
         end if
         i = j + 1
      end do
   end function bad_token

   !> Every numeric token of `text` (the captured lines) parses as a real.
   subroutine check_readable(text, what)
      character(len=*), intent(in) :: text(:), what
      integer :: k
      character(len=:), allocatable :: bad
      call check(size(text) > 1, what//': printed a table')
      do k = 1, size(text)
         bad = bad_token(text(k))
         if (len(bad) > 0) then
            call check(.false., what//": unreadable number '"//bad//"' in: "//trim(text(k)))
            return
         end if
      end do
      call check(.true., what//': every number readable')
   end subroutine check_readable

   !> `what` printed a forced 1e120 as the clamped value.
   subroutine check_clamped(what)
      character(len=*), intent(in) :: what
      call check(lines_contain(lines, clamped), what//': 1e120 prints as '//clamped)
   end subroutine check_clamped

   !> The sample tokens the checker must reject and accept (guards the test).
   subroutine check_checker()
      call check(len(bad_token('       1   1.22047-102   2.00000E+00')) > 0, &
                 'checker rejects 1.22047-102')
      call check(len(bad_token('   1.00000+120')) > 0, 'checker rejects 1.00000+120')
      call check(len(bad_token('  3 (1.5E+00, -2.5) 0.000 s, 12 cycles/s X-VEL S-F --')) == 0, &
                 'checker accepts readable numbers and words')
   end subroutine check_checker

   !> Rigid blocks: two blocks side by side with their contacts; block,
   !> corner, contact, domain and history values forced to +-1e-120 / 1e120.
   subroutine test_rigid_tables()
      integer(ip) :: n, b, c, k
      call check_checker()
      call fresh()
      call run('ROUND 0.01')
      call run('BLOCK 0,0 0,10 10,10 10,0')
      call run('SPLIT 5,-1 5,11')
      call run('PROP MAT=1 DENS=2000 COH=1e-120 TENS=1e120')
      call run('PROP JMAT=1 JKN=1e9 JKS=1e9')
      call run('HIST XVEL 0,0 NCYC 1')
      call run('HIST YDIS 10,10 NCYC 1')
      call run('CYCLE 3')
      call check(session%nerrors == 0, 'rigid model: the deck runs')
      call check(session%model%geometry%contacts%n > 0, 'rigid model: contacts exist')
      if (session%model%geometry%contacts%n == 0) return
      ! the first live block, corner and contact (SPLIT leaves dead entries)
      b = findloc(session%model%geometry%blocks%live(1:session%model%geometry%blocks%n), &
                  .true., 1)
      c = findloc(session%model%geometry%corners%live(1:session%model%geometry%corners%n), &
                  .true., 1)
      k = findloc(session%model%geometry%contacts%live(1:session%model%geometry%contacts%n), &
                  .true., 1)
      call check(b > 0 .and. c > 0 .and. k > 0, 'rigid model: live block, corner, contact')
      if (b == 0 .or. c == 0 .or. k == 0) return
      associate (blk => session%model%geometry%blocks)
         blk%mass(b) = tiny_v; blk%vx(b) = huge_v; blk%vy(b) = -tiny_v
         blk%vr(b) = -huge_v; blk%ux(b) = tiny_v; blk%uy(b) = huge_v; blk%rot(b) = -tiny_v
         blk%area(b) = huge_v
      end associate
      associate (dom => session%model%geometry%domains)
         where (dom%live(1:dom%n)) dom%area(1:dom%n) = -huge_v
      end associate
      session%model%geometry%corners%radius(c) = huge_v
      associate (st => session%model%geometry%contacts%state)
         st%fn(k) = tiny_v; st%fs(k) = huge_v; st%us(k) = -huge_v; st%un(k) = tiny_v
      end associate
      n = session%model%hist%nsample
      call check(n >= 3, 'rigid model: history samples recorded')
      if (n < 3) return
      session%model%hist%values(1, 1) = tiny_v
      session%model%hist%values(1, 2) = huge_v
      session%model%hist%values(2, 1) = -huge_v
      session%model%hist%values(2, 3) = -tiny_v
      session%model%hist%time(1) = tiny_v
      session%model%mech%time = huge_v
      session%model%mech%unbalanced = tiny_v

      call run('PRINT BLOCK')
      call check_readable(lines, 'PRINT BLOCK')
      call check_clamped('PRINT BLOCK')
      call run('PRINT RIGID')
      call check_readable(lines, 'PRINT RIGID')
      call check_clamped('PRINT RIGID')
      ! es14.5 columns kept: (i8,7es14.5,l4) is 110 characters
      call check_equal(len_trim(lines(2)), 110, 'PRINT RIGID: row width kept')
      call run('PRINT CORNER')
      call check_readable(lines, 'PRINT CORNER')
      call check_clamped('PRINT CORNER')
      call run('PRINT CONTACT STATE DISP FORCE')
      call check_readable(lines, 'PRINT CONTACT')
      call check_clamped('PRINT CONTACT')
      call run('PRINT JOINT 5,-1 5,11')
      call check_readable(lines, 'PRINT JOINT')
      call check_clamped('PRINT JOINT')
      call run('PRINT DOMAIN')
      call check_readable(lines, 'PRINT DOMAIN')
      call check_clamped('PRINT DOMAIN')
      call run('PRINT MAX')
      call check_readable(lines, 'PRINT MAX')
      call check_clamped('PRINT MAX')
      call run('PRINT STATUS')
      call check_readable(lines, 'PRINT STATUS')
      call check_clamped('PRINT STATUS')
      call run('PRINT HIST')
      call check_readable(lines, 'PRINT HIST (list)')
      call run('PRINT HIST 1 2')
      call check_readable(lines, 'PRINT HIST 1 2')
      call check_clamped('PRINT HIST 1 2')
      call check(lines_contain(lines, '   0.00000E+00'), 'PRINT HIST: 1e-120 prints as 0')
      call run('PRINT HMAX')
      call check_readable(lines, 'PRINT HMAX')
      call check_clamped('PRINT HMAX')
      call run('PRINT PROP')
      call check_readable(lines, 'PRINT PROP')
      ! PROPERTY column es14.6: 1e120 clamps to the largest 7-digit value
      call check(lines_contain(lines, '9.999999E+99'), 'PRINT PROP: 1e120 clamped')
      call check(lines_contain(lines, 'COHESION      0.000000E+00'), 'PRINT PROP: 1e-120 as 0')
   end subroutine test_rigid_tables

   !> A zoned block with a stress boundary: gridpoint, zone and boundary
   !> values forced to +-1e-120 / 1e120; PRINT STRESS and its file.
   subroutine test_zone_tables()
      integer :: u, ios
      character(len=200) :: line
      character(len=200), allocatable :: file_lines(:)
      call fresh()
      call run('BLOCK 0,0 0,2 2,2 2,0')
      call run('PROP MAT=1 DENS=1e-120')
      call run('GEN QUAD 0.5')
      call run('BOUND STRESS -1 -0.5 -2')
      call check(session%nerrors == 0, 'zoned model: the deck runs')
      call check(session%model%geometry%zones%n > 0 .and. session%model%bound%n > 1, &
                 'zoned model: zones and boundary points exist')
      if (session%model%geometry%zones%n == 0 .or. session%model%bound%n < 2) return
      associate (gp => session%model%geometry%gridpoints)
         gp%vx(1) = huge_v; gp%vy(1) = tiny_v; gp%ux(1) = -huge_v; gp%uy(1) = -tiny_v
         gp%fx(2) = tiny_v; gp%fy(2) = huge_v; gp%mass(3) = tiny_v
      end associate
      associate (zn => session%model%geometry%zones)
         zn%sxx = tiny_v; zn%syy = -huge_v; zn%sxy = tiny_v; zn%szz = huge_v
      end associate
      associate (b => session%model%bound)
         b%fx(1) = tiny_v; b%dfx(1) = huge_v; b%dfy(1) = -tiny_v; b%xmul(2) = tiny_v
         b%ymul(2) = huge_v
      end associate

      call run('PRINT GRIDPOINT DISP')
      call check_readable(lines, 'PRINT GRIDPOINT DISP')
      call check_clamped('PRINT GRIDPOINT DISP')
      call run('PRINT GRIDPOINT FORCE')
      call check_readable(lines, 'PRINT GRIDPOINT FORCE')
      call check_clamped('PRINT GRIDPOINT FORCE')
      call run('PRINT GRIDPOINT STATE')
      call check_readable(lines, 'PRINT GRIDPOINT STATE')
      call run('PRINT ZONE STATE')
      call check_readable(lines, 'PRINT ZONE STATE')
      call run('PRINT ZONE STRESS')
      call check_readable(lines, 'PRINT ZONE STRESS')
      call check_clamped('PRINT ZONE STRESS')
      call run('PRINT BOUNDARY')
      call check_readable(lines, 'PRINT BOUNDARY')
      call check_clamped('PRINT BOUNDARY')
      call run('PRINT MAX')
      call check_readable(lines, 'PRINT MAX (zones)')
      call check_clamped('PRINT MAX (zones)')
      call run('PRINT STRESS 0 2 0 2 2 2')
      call check_readable(lines, 'PRINT STRESS')
      call check_clamped('PRINT STRESS')
      ! the same lines in the file STRESS
      allocate (file_lines(0))
      open (newunit=u, file='STRESS', status='old', action='read', iostat=ios)
      call check(ios == 0, 'PRINT STRESS: the file STRESS exists')
      if (ios /= 0) return
      do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         file_lines = [character(len=200) :: file_lines, line]
      end do
      close (u, status='delete')
      call check_readable(file_lines, 'the STRESS file')
   end subroutine test_zone_tables

   !> The per-step and the summary line of CYCLE at a time beyond 1e100.
   subroutine test_cycle_lines()
      call fresh()
      call run('ROUND 0.01')
      call run('BLOCK 0,0 0,10 10,10 10,0')
      call run('SPLIT 5,-1 5,11')
      call run('PROP MAT=1 DENS=2000')
      call run('PROP JMAT=1 JKN=1e9 JKS=1e9')
      call run('FIX 0,5 0,10')
      call run('CYCLE 1')   ! the first CYCLE starts the clock
      session%model%mech%time = huge_v
      call run('CYCLE 2')
      call check(session%nerrors == 0, 'CYCLE at t = 1e120 runs')
      call check_readable(lines, 'CYCLE lines')
      call check(lines_contain(lines, ', time  '//clamped//','), 'CYCLE summary: time clamped')
   end subroutine test_cycle_lines

end program test_print_tiny
