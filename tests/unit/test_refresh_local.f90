!> The search after a cut on a cycled model looks only at the pairs with a
!> block the cut changed (issue 23; contact_refresh geometry_refresh's
!> `since`, engine_cycle search_base): the contact list it leaves must be
!> the one the search over every pair leaves -- the same contacts in the
!> same order, with the same ends, points, normals, lengths, gaps and
!> carried forces, bit for bit.
!>
!> Two sessions run the same deck: a jointed wall settling under gravity
!> (three joint sets), cycled, then twelve cuts at random places (CRACK,
!> TUNNEL, DELETE), each followed by CYCLE 20. After each cut session A's
!> contacts are brought up to date by the local search, session B's by the
!> search over every pair, and the two contact lists are compared element
!> by element (no tolerance: the local search must make the same
!> contacts; a pair it skipped that a cut changed shows as a missing or
!> extra contact). The test also checks that the local search was the one
!> taken (search_base > 0) and that the cuts made contacts at all.
program test_refresh_local
   use core_kinds, only: wp, ip
   use model_geometry, only: geometry_t
   use contact_refresh, only: geometry_refresh
   use engine_cycle, only: search_base
   use commands_session, only: session_t, session_execute_line
   use core_output, only: itoa
   use testing, only: check, check_equal, testing_finish
   use testing_session, only: session_new_quiet, session_lines
   implicit none

   character(len=*), parameter :: deck(*) = [character(len=48) :: &
                                              'ROUND 0.01', &
                                              'BLOCK 0,0 0,6 6,6 6,0', &
                                              'JSET 0,0 80,0 0,0 1,0 0,0', &
                                              'JSET 90,0 80,0 0,0 1,0 0,0', &
                                              'JSET 45,0 80,0 0,0 2.3,0 0,0', &
                                              'PROP MAT=1 DENS=2500', &
                                              'PROP JMAT=1 JKN=1E9 JKS=1E9 JFRIC=0.3', &
                                              'FIX -1,7 -1,0.5', &
                                              'GRAVITY 0 -10', &
                                              'DAMP AUTO', &
                                              'CYCLE 100']
   type(session_t) :: a, b
   character(len=120) :: cut
   integer :: trial, nlocal, ncut
   integer(ip) :: base, nbefore, made
   integer(8) :: state

   call session_new_quiet(a)
   call session_new_quiet(b)
   call session_lines(a, deck)
   call session_lines(b, deck)
   call check(a%model%geometry%mechanical, 'the wall has cycled')
   state = 20261128_8
   nlocal = 0
   ncut = 0
   made = 0
   do trial = 1, 12
      cut = random_cut(trial)
      call session_execute_line(a, trim(cut), 1)
      call session_execute_line(b, trim(cut), 1)
      ! a crack inside one block or a range holding no centroid cuts nothing
      if (a%model%geometry%contacts_valid) cycle
      ncut = ncut + 1
      base = search_base(a%model)
      if (base > 0) nlocal = nlocal + 1
      nbefore = count(a%model%geometry%contacts%live(1:a%model%geometry%contacts%n))
      call geometry_refresh(a%model%geometry, since=base)
      call geometry_refresh(b%model%geometry)
      made = made + max(0_ip, a%model%geometry%contacts%n - nbefore)
      call compare(a%model%geometry, b%model%geometry, 'trial '//itoa(trial)//' ('//trim(cut)//')')
      call session_execute_line(a, 'CYCLE 20', 1)
      call session_execute_line(b, 'CYCLE 20', 1)
   end do
   ! every cut came after a CYCLE with nothing but the cut between: the
   ! local search must have been taken each time
   call check(ncut >= 8, 'at least 8 of the 12 cuts changed blocks')
   call check_equal(nlocal, ncut, 'the local search was taken after each cut')
   call check(made > 0, 'the cuts made new contacts')
   call compare(a%model%geometry, b%model%geometry, 'after the last CYCLE')
   call testing_finish()

contains

   !> A cut at a random place of the wall: CRACK across a few blocks, a
   !> small TUNNEL, or DELETE of the blocks in a small range.
   function random_cut(k) result(line)
      integer, intent(in) :: k
      character(len=120) :: line
      real(wp) :: x1, y1, x2, y2
      x1 = 0.5_wp + 5.0_wp*uniform()
      y1 = 1.0_wp + 4.5_wp*uniform()
      x2 = x1 + 3.0_wp*(uniform() - 0.5_wp)
      y2 = y1 + 3.0_wp*(uniform() - 0.5_wp)
      select case (mod(k, 3))
      case (1)
         write (line, '(a,4(1x,f0.4))') 'CRACK', x1, y1, x2, y2
      case (2)
         write (line, '(a,3(1x,f0.4),a)') 'TUNNEL', x1, y1, 0.2_wp + 0.3_wp*uniform(), ' 8'
      case default
         write (line, '(a,4(1x,f0.4))') 'DELETE', x1 - 0.5_wp, x1 + 0.5_wp, y1 - 0.5_wp, y1 + 0.5_wp
      end select
   end function random_cut

   !> The minimal standard generator (Park and Miller): the same cuts with
   !> every compiler, no integer overflow.
   real(wp) function uniform()
      state = mod(state*16807_8, 2147483647_8)
      uniform = real(state, wp)/2147483647.0_wp
   end function uniform

   !> The two contact lists, element by element (bit for bit).
   subroutine compare(ga, gb, what)
      type(geometry_t), intent(in) :: ga, gb
      character(len=*), intent(in) :: what
      integer(ip) :: n
      logical :: same
      associate (p => ga%contacts, q => gb%contacts)
         call check_equal(int(p%n), int(q%n), what//': number of contacts')
         if (p%n /= q%n) return
         n = p%n
         same = all(p%live(1:n) .eqv. q%live(1:n))
         call check(same, what//': live flags')
         call check(all(p%block1(1:n) == q%block1(1:n)) .and. all(p%block2(1:n) == q%block2(1:n)), &
                    what//': blocks')
         call check(all(p%end1(1:n) == q%end1(1:n)) .and. all(p%end2(1:n) == q%end2(1:n)) .and. &
                    all(p%kind(1:n) == q%kind(1:n)), what//': ends and kinds')
         call check(all(p%x(1:n) == q%x(1:n)) .and. all(p%y(1:n) == q%y(1:n)), what//': points')
         call check(all(p%nx(1:n) == q%nx(1:n)) .and. all(p%ny(1:n) == q%ny(1:n)), &
                    what//': normals')
         call check(all(p%length(1:n) == q%length(1:n)) .and. all(p%gap(1:n) == q%gap(1:n)), &
                    what//': lengths and gaps')
         call check(all(p%state%fn(1:n) == q%state%fn(1:n)) .and. &
                    all(p%state%fs(1:n) == q%state%fs(1:n)), what//': forces carried')
      end associate
      call check(all(ga%corners%radius(1:ga%corners%n) == gb%corners%radius(1:gb%corners%n)), &
                 what//': roundings')
   end subroutine compare

end program test_refresh_local
