!> Timing of the explicit rigid-block cycle (issue 4) for jointed assemblies
!> of about 1k, 10k and 100k blocks: an n x n square of 1 m blocks cut by
!> two orthogonal continuous joint sets (JSET, gap 0, rounding 0.01 m),
!> bottom row fixed, gravity, DAMP AUTO, Mohr-Coulomb joints (JKN = JKS =
!> 1e10 Pa/m, JFRIC 0.5). Everything goes through the command interpreter,
!> as a deck would.
!>
!> For each size and each repeat (a fresh model every time):
!>    set-up    wall time of the first `CYCLE 1`: contact detection and
!>              domains (geometry_refresh), the first contact scan, masses,
!>              joint-law groups, time step, and one step
!>    prepare   wall time of `CYCLE 0` on the cycled model: what every
!>              later CYCLE command pays once before its first step
!>              (contact scan, groups, masses, time step)
!>    cycling   wall time of `CYCLE ncyc`, minus one `prepare`, divided by
!>              ncyc: seconds per cycle; contacts/s = live contacts x ncyc
!>              / that time
!> The table gives the median of the repeats. s/cycle is given as wall time
!> and as processor time of this process (cpu_time), which is what counts
!> when the machine is shared.
!>
!> Usage: rigid_bench [max_blocks [ncyc [repeats [min_blocks]]]]  (defaults 100000 200 3 0):
!> the sizes of about 1k, 10k, 100k, 1M blocks from min_blocks to max_blocks.
!> After each table row a line `rigid_bench: blocks=.. contacts=.. s_per_cycle=..
!> Mcontact_cycles_per_s=..` (medians) for scripts (bench/ratios.py). Before it,
!> PRINT CYCLE of the last repeat: the stages the model runs and each one's
!> share of the timed CYCLE's wall time. Then a line `rigid_bench order: ..`
!> (issue 23, storage order of the last repeat's model, see order_report).
program rigid_bench
   use core_kinds, only: wp, ip, i8
   use core_error, only: error_t
   use commands_session, only: session_t, session_init
   use bench_common, only: median, exec
   use model_geometry, only: geometry_live_blocks
   implicit none
   integer(ip), parameter :: targets(4) = [1000, 10000, 100000, 1000000]
   integer(ip), parameter :: sides(4) = [32, 100, 317, 1000]   ! 1 024, 10 000, 100 489, 1e6 blocks
   integer(ip) :: k, maxb, minb, ncyc, nrep
   character(len=32) :: arg
   maxb = 100000
   ncyc = 200
   nrep = 3
   minb = 0
   if (command_argument_count() > 0) then
      call get_command_argument(1, arg)
      read (arg, *) maxb
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
      read (arg, *) minb
   end if
   write (*, '(a,i0,a,i0,a)') 'rigid_bench: ', ncyc, ' cycles, median of ', nrep, ' repeats'
   write (*, '(a)') '  blocks  contacts   build_s   setup_s  prepare_s  s/cycle(wall)' // &
      '  s/cycle(cpu)  contacts/s(wall)   unbalanced'
   do k = 1, size(sides)
      if (targets(k) <= maxb .and. targets(k) >= minb) call run(sides(k))
   end do

contains

   subroutine run(n)
      integer(ip), intent(in) :: n
      type(session_t) :: s
      type(error_t), allocatable :: error
      real(wp) :: tb(nrep), ts(nrep), tp(nrep), tc(nrep), rate(nrep), t0, t1, unbal
      real(wp) :: cp(nrep), cc(nrep), c0, c1
      integer(ip) :: r, nblocks, ncont
      character(len=120) :: line
      do r = 1, nrep
         call session_init(s, error)
         s%out%screen = .false.
         t0 = now()
         write (line, '(a,4(i0,a))') 'BLOCK 0,0 0,', n, ' ', n, ',', n, ' ', n, ',0'
         call exec(s, 'ROUND 0.01')
         call exec(s, trim(line))
         write (line, '(a,i0,a)') 'JSET 0,0 ', 10*n, ',0 0,0 1,0 0,0'
         call exec(s, trim(line))
         write (line, '(a,i0,a)') 'JSET 90,0 ', 10*n, ',0 0,0 1,0 0,0'
         call exec(s, trim(line))
         write (line, '(a,i0,a)') 'FIX -1,', n + 1, ' -1,1'
         call exec(s, 'PROP MAT=1 DENS=2500')
         call exec(s, 'PROP JMAT=1 JKN=1E10 JKS=1E10 JFRIC=0.5')
         call exec(s, trim(line))
         call exec(s, 'GRAVITY 0 -10')
         call exec(s, 'DAMP AUTO')
         t1 = now()
         tb(r) = t1 - t0
         t0 = now()
         call exec(s, 'CYCLE 1')
         t1 = now()
         ts(r) = t1 - t0
         call cpu_time(c0)
         t0 = now()
         call exec(s, 'CYCLE 0')
         t1 = now()
         call cpu_time(c1)
         tp(r) = t1 - t0
         cp(r) = c1 - c0
         write (line, '(a,i0)') 'CYCLE ', ncyc
         call cpu_time(c0)
         t0 = now()
         call exec(s, trim(line))
         t1 = now()
         call cpu_time(c1)
         tc(r) = max(t1 - t0 - tp(r), 1.0e-9_wp)/real(ncyc, wp)
         cc(r) = max(c1 - c0 - cp(r), 1.0e-9_wp)/real(ncyc, wp)
         nblocks = geometry_live_blocks(s%model%geometry)
         ncont = count(s%model%geometry%contacts%live(1:s%model%geometry%contacts%n))
         rate(r) = real(ncont, wp)/tc(r)
         unbal = s%model%mech%unbalanced
         if (s%nerrors > 0) then
            write (*, '(a,i0,a)') 'rigid_bench: ', s%nerrors, ' command error(s); timings are void'
            error stop 1
         end if
         if (r == nrep) then
            ! each stage's share of the last timed CYCLE (issue 23: a
            ! mechanics-only scene runs no zone, fluid or thermal stage)
            s%out%screen = .true.
            call exec(s, 'PRINT CYCLE')
            call order_report(s)
         end if
      end do
      write (*, '(i8,i10,3f10.3,es15.3,es14.3,es18.3,es13.3)') nblocks, ncont, median(tb), &
         median(ts), median(tp), median(tc), median(cc), median(rate), unbal
      write (*, '(a,i0,a,i0,a,es12.5,a,f0.4)') 'rigid_bench: blocks=', nblocks, ' contacts=', ncont, &
         ' s_per_cycle=', median(tc), ' Mcontact_cycles_per_s=', median(rate)/1.0e6_wp
   end subroutine run

   !> How spatially coherent the storage order is (issue 23): the mean
   !> distance between the centroids of blocks with consecutive live ids (in
   !> block widths: 1 for a walk through neighbours), the share of blocks
   !> whose corner ids are one contiguous run (a ring walk on consecutive
   !> slots), and, over the contact list in stored order, the mean jump of
   !> the first block's id and of the first corner's id from one contact to
   !> the next (its corner, or for an edge-corner contact its edge: a
   !> gather's reuse distance in records).
   subroutine order_report(s)
      type(session_t), intent(in) :: s
      integer(ip) :: b, prev, nb, c, k, lo, hi, ncont, nrun, pb, pc
      real(wp) :: dsum, jb, jc
      associate (g => s%model%geometry)
         dsum = 0; nb = 0; prev = 0; nrun = 0
         do b = 1, g%blocks%n
            if (.not. g%blocks%live(b)) cycle
            if (prev > 0) then
               dsum = dsum + hypot(g%blocks%xc(b) - g%blocks%xc(prev), g%blocks%yc(b) - g%blocks%yc(prev))
               nb = nb + 1
            end if
            prev = b
            c = g%blocks%first_corner(b); lo = c; hi = c
            do k = 2, g%blocks%ncorner(b)
               c = g%corners%next(c); lo = min(lo, c); hi = max(hi, c)
            end do
            if (hi - lo + 1 == g%blocks%ncorner(b)) nrun = nrun + 1
         end do
         jb = 0; jc = 0; ncont = 0; pb = 0; pc = 0
         do k = 1, g%contacts%n
            if (.not. g%contacts%live(k)) cycle
            if (pb > 0) then
               jb = jb + abs(g%contacts%block1(k) - pb)
               jc = jc + abs(g%contacts%end1(k) - pc)
               ncont = ncont + 1
            end if
            pb = g%contacts%block1(k); pc = g%contacts%end1(k)
         end do
         write (*, '(a,f0.3,a,f0.4,a,f0.1,a,f0.1)') 'rigid_bench order: block step ', &
            dsum/max(nb, 1), ' corner runs ', real(nrun, wp)/max(nb + 1, 1), &
            ' contact block jump ', jb/max(ncont, 1), ' contact corner jump ', jc/max(ncont, 1)
      end associate
   end subroutine order_report

   real(wp) function now()
      integer(i8) :: count, rate
      call system_clock(count, rate)
      now = real(count, wp)/real(rate, wp)
   end function now

end program rigid_bench
