!> Timing of the zone cycle of fully-deformable blocks (issue 6): one
!> square block of side n m zoned by `GENERATE QUAD 1` (each 1 m cell cut
!> by both diagonals into 4 triangles: 4 n^2 zones), elastic (CONS 1),
!> base fixed vertically (BOUNDARY YVEL 0), gravity, DAMP AUTO; sizes of
!> about 10k, 100k and 1M zones. Everything goes through the command
!> interpreter, as a deck would.
!>
!> For each size and each repeat (a fresh model every time):
!>    zoning    wall time of the GENERATE command
!>    cycling   (wall time of CYCLE ncyc - CYCLE 0) / ncyc: seconds per
!>              cycle; zone updates/s = zones x ncyc / that time
!> The table gives the median of the repeats, wall time and processor
!> time (cpu_time) of this process.
!>
!> Usage: zone_bench [max_zones [ncyc [repeats [MC|EL [min_zones]]]]]  (defaults 1000000 100 3 EL 0)
!> After each table row a line `zone_bench: zones=.. s_per_cycle=.. Mzone_updates_per_s=..`
!> (medians) for scripts (bench/ratios.py). Before each table row, PRINT CYCLE
!> of the last repeat: the stages the model runs and each one's share of the
!> timed CYCLE's wall time.
!> MC: the block zoned by `GENERATE AUTO 0.75` (about as many zones) and
!> given the Mohr-Coulomb model (CONS 3, c 1e6, 30 degrees, elastic under
!> gravity here), so every zone runs the plastic model and the paired mixed
!> discretization (zones_mixed): the cost of switching plasticity on.
program zone_bench
   use core_kinds, only: wp, ip, i8
   use core_error, only: error_t
   use commands_session, only: session_t, session_init
   use bench_common, only: median, exec
   implicit none
   integer(ip), parameter :: sides(3) = [50, 158, 500]    ! 10 000, 99 856, 1 000 000 zones
   integer(ip) :: k, maxz, minz, ncyc, nrep
   character(len=32) :: arg
   logical :: mc = .false.
   maxz = 1000000
   ncyc = 100
   nrep = 3
   minz = 0
   if (command_argument_count() > 0) then
      call get_command_argument(1, arg)
      read (arg, *) maxz
   end if
   if (command_argument_count() > 1) then
      call get_command_argument(2, arg)
      read (arg, *) ncyc
   end if
   if (command_argument_count() > 2) then
      call get_command_argument(3, arg)
      read (arg, *) nrep
   end if
   if (command_argument_count() > 3) then
      call get_command_argument(4, arg)
      mc = trim(arg) == 'MC' .or. trim(arg) == 'mc'
   end if
   if (command_argument_count() > 4) then
      call get_command_argument(5, arg)
      read (arg, *) minz
   end if
   print '(a)', '|   zones | gridpoints | zoning [s] | s/cycle (wall) | s/cycle (cpu) | zone updates/s |'
   print '(a)', '|---------|------------|------------|----------------|---------------|----------------|'
   do k = 1, size(sides)
      if (4_ip*sides(k)**2 > maxz) exit
      if (4_ip*sides(k)**2 < minz) cycle
      call one_size(sides(k))
   end do

contains

   subroutine one_size(n)
      integer(ip), intent(in) :: n
      real(wp) :: tz(nrep), tw(nrep), tc(nrep)
      integer(ip) :: r, nz, ng
      do r = 1, nrep
         call one_run(n, ncyc, r == nrep, tz(r), tw(r), tc(r), nz, ng)
      end do
      print '(a,i8,a,i11,a,f11.3,a,es15.4,a,es14.4,a,es15.4,a)', '|', nz, ' |', ng, ' |', median(tz), &
         ' |', median(tw), ' |', median(tc), ' |', real(nz, wp)/median(tw), ' |'
      print '(a,i0,a,es12.5,a,f0.4)', 'zone_bench: zones=', nz, ' s_per_cycle=', median(tw), &
         ' Mzone_updates_per_s=', real(nz, wp)/median(tw)/1.0e6_wp
   end subroutine one_size

   subroutine one_run(n, ncyc, stages, tzone, twall, tcpu, nz, ng)
      integer(ip), intent(in) :: n, ncyc
      logical, intent(in) :: stages   !< print PRINT CYCLE after the timed CYCLE
      real(wp), intent(out) :: tzone, twall, tcpu
      integer(ip), intent(out) :: nz, ng
      type(session_t) :: s
      type(error_t), allocatable :: error
      character(len=120) :: line
      integer(i8) :: t0, t1, t2, t3, rate
      real(wp) :: c0, c1, c2
      call session_init(s, error)
      s%out%screen = .false.
      write (line, '(a,4(i0,a))') 'BLOCK 0,0 0,', n, ' ', n, ',', n, ' ', n, ',0'
      call exec(s, 'ROUND 0.01')
      call exec(s, trim(line))
      call system_clock(t0, rate)
      if (mc) then
         call exec(s, 'GENERATE AUTO 0.75')
      else
         call exec(s, 'GENERATE QUAD 1')
      end if
      call system_clock(t1)
      tzone = real(t1 - t0, wp)/real(rate, wp)
      call exec(s, 'PROP MAT=1 DENS=2500 K=1E10 G=6E9 JKN=1E10 JKS=1E10')
      if (mc) then
         call exec(s, 'CHANGE CONS=3')
         call exec(s, 'PROP MAT=1 COH=1E6 FRIC=0.577 TENS=1E5')
      end if
      call exec(s, 'GRAVITY 0 -10')
      write (line, '(a,i0,a)') 'BOUNDARY -1,', n + 1, ' -0.1,0.1 YVEL=0'
      call exec(s, trim(line))
      call exec(s, 'DAMP AUTO')
      call system_clock(t0)
      call cpu_time(c0)
      call exec(s, 'CYCLE 0')
      call system_clock(t1)
      call cpu_time(c1)
      write (line, '(a,i0)') 'CYCLE ', ncyc
      call system_clock(t2)
      call exec(s, trim(line))
      call system_clock(t3)
      call cpu_time(c2)
      twall = (real(t3 - t2, wp) - real(t1 - t0, wp))/real(rate, wp)/real(ncyc, wp)
      tcpu = ((c2 - c1) - (c1 - c0))/real(ncyc, wp)
      if (stages) then
         ! each stage's share of the timed CYCLE (issue 23: an elastic zoned
         ! block runs no contact, fluid or thermal stage)
         s%out%screen = .true.
         call exec(s, 'PRINT CYCLE')
      end if
      nz = count(s%model%geometry%zones%live(1:s%model%geometry%zones%n))
      ng = count(s%model%geometry%gridpoints%live(1:s%model%geometry%gridpoints%n))
   end subroutine one_run

end program zone_bench
