!> Random jointed-rock scenes as a user writes them (issue 18, label
!> `stability`): 1000 seeds of 1 to 4 joint sets (any angle, spacing, trace
!> and gap with deviations; continuous or not), ROUND from 1e-3 to 0.2 of the
!> mean spacing, with and without a TUNNEL (before or after the sets), rigid
!> and (one seed in ten) fully deformable. Properties of every scene:
!>   - block areas add up to the BLOCK's area within 1e-9 relative (each
!>     block simple and clockwise; contact_checks' check_blocks);
!>   - no block edge shorter than the minimum edge EDGE (the cut ends and
!>     crack-path bends nearer than EDGE to a corner are moved onto it);
!>   - every contact of the freshly cut model has a gap >= -1e-9 of the
!>     mean block size (a tightly fitted mosaic touches and never overlaps:
!>     corner rounding is reduced where a corner's circle would reach
!>     through its block);
!>   - after the tunnel's inside is deleted, 200 cycles under gravity with
!>     the bottom held (rigid blocks: FIX; zoned blocks, which cannot be
!>     fixed (manual Section 4.5, FIX): BOUNDARY XVEL 0 YVEL 0 on the base)
!>     end without an error.
program test_stability_scenes_random
   use core_kinds, only: wp, ip, i8
   use core_error, only: error_t
   use model_geometry, only: geometry_t, geometry_init, geometry_set_seed, geometry_random, &
                             geometry_live_blocks, geometry_total_area, geometry_block_polygon
   use contact_refresh, only: geometry_refresh
   use contact_checks, only: check_blocks
   use testing, only: check, check_equal, testing_finish
   use commands_session, only: session_t, session_init, session_execute_line
   use testing_session, only: smallest_gap, scene_log_t
   implicit none

   integer, parameter :: nseed = 1000
   integer :: seed, nzoned, ntunnel
   type(scene_log_t) :: log
   integer(i8) :: nblocks
   type(geometry_t) :: rng
   ! the scene being run, for the failure messages
   type(session_t) :: s
   integer :: nsets
   logical :: tunnel, first, zoned

   nblocks = 0
   nzoned = 0
   ntunnel = 0
   do seed = 1, nseed
      call scene(seed)
   end do
   print '(a,i0,a,f7.1,a,i0,a,i0,a)', 'scenes: ', nseed, ', mean blocks ', &
      real(nblocks)/nseed, ', ', ntunnel, ' with a tunnel, ', nzoned, ' zoned'
   call check_equal(log%nfail(1), 0, 'scenes whose block areas do not add up')
   call check_equal(log%nfail(2), 0, 'scenes with an edge shorter than EDGE')
   call check_equal(log%nfail(3), 0, 'scenes with a contact overlapped at cycle 0')
   call check_equal(log%nfail(4), 0, 'scenes whose 200 cycles under gravity end in an error')
   call check(real(nblocks)/nseed > 10.0, 'the scenes have many blocks')
   call testing_finish()

contains

   real(wp) function r()
      r = geometry_random(rng)
   end function r

   subroutine scene(seed)
      integer, intent(in) :: seed
      type(error_t), allocatable :: error
      character(len=120) :: line
      character(len=120), allocatable :: sets(:)
      integer :: k, nside
      real(wp) :: spacing, round, a, ad, t, td, g, gd, sp, sd, xc, yc, rt, gmin, size
      call log%start(seed)
      call geometry_init(rng)
      call geometry_set_seed(rng, int(seed, i8) + 7919_i8)
      call session_init(s, error)
      s%out%screen = .false.
      nsets = 1 + min(3, int(4.0_wp*r()))
      spacing = 1.2_wp + 1.8_wp*r()
      round = spacing*10.0_wp**(-3.0_wp + log10(200.0_wp)*r())
      tunnel = r() < 0.5_wp
      first = r() < 0.5_wp
      zoned = r() < 0.1_wp
      allocate (sets(nsets))
      do k = 1, nsets
         a = 180.0_wp*r()
         ad = 10.0_wp*r()
         if (r() < 0.5_wp) then
            t = 100.0_wp; td = 0.0_wp; g = 0.0_wp; gd = 0.0_wp
         else
            t = 2.0_wp + 6.0_wp*r(); td = r(); g = 0.5_wp + 1.5_wp*r(); gd = 0.5_wp*g*r()
         end if
         sp = spacing*(0.7_wp + 0.6_wp*r())
         sd = 0.3_wp*sp*r()
         write (sets(k), '(a,8(g0.6,a))') 'JSET ', a, ',', ad, ' ', t, ',', td, ' ', g, ',', gd, &
            ' ', sp, ',', sd
      end do
      xc = 3.5_wp + 3.0_wp*r()
      yc = 3.5_wp + 3.0_wp*r()
      rt = 1.0_wp + 1.5_wp*r()
      nside = 12 + int(9.0_wp*r())
      write (line, '(a,i0)') 'SET SEED ', seed
      call do(line)
      write (line, '(a,g0.8)') 'ROUND ', round
      call do(line)
      call do('BLOCK 0,0 0,10 10,10 10,0')
      write (line, '(a,3(g0.6,a),i0)') 'TUNNEL ', xc, ' ', yc, ' ', rt, ' ', nside
      if (tunnel .and. first) call do(line)
      do k = 1, nsets
         call do(trim(sets(k)))
      end do
      if (tunnel .and. .not. first) call do(line)
      nblocks = nblocks + geometry_live_blocks(s%model%geometry)
      if (tunnel) ntunnel = ntunnel + 1
      ! area
      call check_blocks(s%model%geometry, 1.0e-9_wp, error)
      if (allocated(error)) call fail(1, error%message)
      ! edges
      if (shortest_edge(s%model%geometry) < s%model%geometry%edge_min - &
          s%model%geometry%tol) call fail(2, 'edge shorter than EDGE')
      ! overlap at cycle 0
      call geometry_refresh(s%model%geometry, force=.true.)
      call smallest_gap(s%model%geometry, gmin, size)
      if (gmin < -1.0e-9_wp*size) then
         write (line, '(a,es10.3,a,es10.3)') 'gap ', gmin, ' mean block size ', size
         call fail(3, trim(line))
      end if
      ! 200 cycles under gravity
      if (tunnel) then
         write (line, '(a,3(g0.6,a))') 'DELETE ANN ', xc, ' ', yc, ' 0 ', 0.9_wp*rt
         call do(line)
      end if
      call do('PROP MAT=1 DENS=2600 K=2E10 G=1E10')
      call do('PROP JMAT=1 JKN=1E10 JKS=1E10 JFRIC=0.5')
      if (zoned) then
         nzoned = nzoned + 1
         write (line, '(a,g0.6)') 'GENERATE AUTO ', spacing
         call do(line)
      end if
      if (zoned) then
         call do('BOUND -1,11 -0.01,0.01 XVEL 0 YVEL 0')
      else
         call do('FIX -1,11 -1,0.5')
      end if
      call do('GRAVITY 0 -10')
      call do('DAMP AUTO')
      if (s%nerrors == 0) then
         call do('CYCLE 200')
         if (s%nerrors > 0) call fail(4, 'CYCLE 200 ended in an error')
      else
         call fail(4, 'a set-up command failed')
      end if
   end subroutine scene

   subroutine do(text)
      character(len=*), intent(in) :: text
      call log%run(s, text)
   end subroutine do

   subroutine fail(what, why)
      integer, intent(in) :: what
      character(len=*), intent(in) :: why
      call log%fail(what, why)
   end subroutine fail

   real(wp) function shortest_edge(geo) result(emin)
      type(geometry_t), intent(in) :: geo
      real(wp), allocatable :: x(:), y(:)
      integer(ip) :: b, i, n
      emin = huge(1.0_wp)
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         call geometry_block_polygon(geo, b, x, y)
         n = size(x)
         do i = 1, n
            emin = min(emin, hypot(x(merge(1_ip, i + 1_ip, i == n)) - x(i), &
                                   y(merge(1_ip, i + 1_ip, i == n)) - y(i)))
         end do
      end do
   end function shortest_edge

end program test_stability_scenes_random
