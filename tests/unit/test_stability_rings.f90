!> TUNNEL rings against joints that graze them (label `stability`): 400
!> seeds of a 20 m square cut by two JSETs (continuous or with gaps, any
!> angles), then a TUNNEL of 12 to 32 sides, radius 1.5 to 3 m, ROUND 0.01 to
!> 0.05 m. In every other seed one joint of the first set is laid at the
!> ring's apothem give or take 3 % of the radius, so that it grazes the
!> ring: a corner a few centimetres past the joint, or the joint a few
!> centimetres outside a corner (the lead's seed 234, e2e.tunnel_grazing).
!> Properties of every scene:
!>   - few cuts of the TUNNEL are refused (a sliver between the joint and
!>     the ring's sides is merged or never made: the ring's corners that
!>     near the joint lie on it); the rest are debts, bounded (see below);
!>   - block areas add up to the square's area within 1e-9 relative, after
!>     the TUNNEL and after DELETE ANN of its inside (to the square minus
!>     the hole; contact_checks' check_blocks);
!>   - no block the TUNNEL made or changed is smaller than 1/500 of the mean
!>     block, the fraction below which GENERATE names a zone as setting the
!>     time step (commands_zones, warn_small_zone): before the fix the
!>     seed-234 ring left a 4 cm sliver whose zone was 1/1760 of the mean;
!>   - every contact of the cut model has a gap >= -1e-9 of the mean block
!>     size (the blocks fit without overlap, as in
!>     stability.test_stability_scenes_random).
program test_stability_rings
   use core_kinds, only: wp, ip, i8
   use core_constants, only: pi
   use core_error, only: error_t
   use model_geometry, only: geometry_t, geometry_init, geometry_set_seed, geometry_random, &
                             geometry_live_blocks, geometry_total_area, geometry_refused_cuts, &
                             cut_refused_sliver, cut_refused_shape
   use contact_refresh, only: geometry_refresh
   use contact_checks, only: check_blocks
   use testing, only: check, check_equal, testing_finish
   use commands_session, only: session_t, session_init, session_execute_line
   use testing_session, only: smallest_gap, scene_log_t
   implicit none

   integer, parameter :: nseed = 400
   !> below this fraction of the mean block a block made by the ring fails
   real(wp), parameter :: small_fraction = 1.0_wp/500.0_wp
   integer :: seed, ngraze
   type(scene_log_t) :: log
   integer(ip) :: nshort
   real(wp) :: worst
   type(geometry_t) :: rng
   type(session_t) :: s

   nshort = 0
   ngraze = 0
   worst = huge(1.0_wp)
   do seed = 1, nseed
      call scene(seed)
   end do
   print '(a,i0,a,i0,a,es10.3,a,i0)', 'rings: ', nseed, ', ', ngraze, &
      ' with a grazing joint; smallest ring block / mean block ', worst, &
      '; cuts refused for an edge below EDGE ', nshort
   ! debts (session 40), bounds at what this version does, so that a change
   ! that refuses more fails: 4 rings of 400 (seeds 38, 98 and 126 among
   ! them) still refuse a sliver cut with
   ! the snap reach of 5 degrees (10 degrees left none, but moved the
   ! opening of examples.geometry_scenes 1.6 % off its polygon); 13 cuts are
   ! refused for an edge below EDGE, each seen (seeds 154, 161) a chain of
   ! the gapped set's pending joints (two crossing at 8 degrees, ends 5 cm
   ! apart) that the ring's new edges complete, not the ring itself
   call check(log%nfail(1) <= 4, 'at most 4 rings with a cut refused for a sliver or a bad shape')
   call check(nshort <= 13, 'at most 13 cuts of 400 rings refused for a short edge')
   call check_equal(log%nfail(2), 0, 'scenes whose block areas do not add up')
   call check_equal(log%nfail(3), 0, 'rings that made a block below 1/500 of the mean')
   call check_equal(log%nfail(4), 0, 'scenes with a contact overlapped at cycle 0')
   call check_equal(log%nfail(5), 0, 'scenes with a command in error')
   call check(ngraze > nseed/3, 'many rings are grazed by a joint')
   call testing_finish()

contains

   real(wp) function r()
      r = geometry_random(rng)
   end function r

   subroutine scene(seed)
      integer, intent(in) :: seed
      type(error_t), allocatable :: error
      character(len=160) :: line
      integer :: nside
      integer, parameter :: sides(5) = [12, 16, 20, 24, 32]
      integer(ip) :: nref0, b, stats0(2)
      real(wp), allocatable :: area0(:)
      real(wp) :: round, a1, a2, xc, yc, rt, apo, dist, ox, oy, gmin, bsize, mean, amin, s1
      logical :: graze
      call log%start(seed)
      call geometry_init(rng)
      call geometry_set_seed(rng, int(seed, i8) + 104729_i8)
      call session_init(s, error)
      s%out%screen = .false.
      round = 0.01_wp + 0.04_wp*r()
      a1 = 180.0_wp*r() - 90.0_wp
      a2 = a1 + 35.0_wp + 75.0_wp*r()
      xc = 8.0_wp + 4.0_wp*r()
      yc = 8.0_wp + 4.0_wp*r()
      rt = 1.5_wp + 1.5_wp*r()
      nside = sides(1 + min(4, int(5.0_wp*r())))
      s1 = 1.5_wp + 1.5_wp*r()
      graze = mod(seed, 2) == 0
      ! the first set's origin: on a joint at the apothem (+-3 % of the
      ! radius) when grazing, anywhere near the ring otherwise
      apo = rt*cos(pi/real(nside, wp))
      if (graze) then
         dist = apo + 0.03_wp*rt*(2.0_wp*r() - 1.0_wp)
         ngraze = ngraze + 1
      else
         dist = s1*r()
      end if
      ! the joint's normal: the set's direction turned by 90 degrees
      ox = xc + dist*cos((a1 + 90.0_wp)*pi/180.0_wp)
      oy = yc + dist*sin((a1 + 90.0_wp)*pi/180.0_wp)
      write (line, '(a,i0)') 'SET SEED ', seed
      call do(line)
      write (line, '(a,g0.6)') 'ROUND ', round
      call do(line)
      call do('BLOCK 0,0 0,20 20,20 20,0')
      write (line, '(a,g0.8,a,g0.8,a,g0.8,a,g0.8,a)') 'JSET ', a1, ',0 40,0 0,0 ', s1, ',0 (', &
         ox, ',', oy, ')'
      call do(line)
      if (r() < 0.5_wp) then
         write (line, '(a,g0.6,a,g0.6,a)') 'JSET ', a2, ',0 40,0 0,0 ', 1.5_wp + 1.5_wp*r(), ',0'
      else
         write (line, '(a,g0.6,a,g0.6,a)') 'JSET ', a2, ',5 6,1 2,0.4 ', 1.5_wp + 1.5_wp*r(), &
            ',0.3'
      end if
      call do(line)
      nref0 = geometry_refused_cuts(s%model%geometry)
      stats0 = s%model%geometry%cut_stats([cut_refused_sliver, cut_refused_shape])
      area0 = s%model%geometry%blocks%area(1:s%model%geometry%blocks%n)
      write (line, '(a,3(g0.8,a),i0)') 'TUNNEL ', xc, ' ', yc, ' ', rt, ' ', nside
      call do(line)
      associate (geo => s%model%geometry)
         if (any(geo%cut_stats([cut_refused_sliver, cut_refused_shape]) /= stats0)) &
            call fail(1, 'the TUNNEL refused a cut for a sliver or a bad shape')
         nshort = nshort + geometry_refused_cuts(geo) - nref0
         call check_blocks(geo, 1.0e-9_wp, error)
         if (allocated(error)) call fail(2, error%message)
         call geometry_refresh(geo, force=.true.)
         call smallest_gap(geo, gmin, bsize)
         if (gmin < -1.0e-9_wp*bsize) then
            write (line, '(a,es10.3,a,es10.3)') 'gap ', gmin, ' mean block size ', bsize
            call fail(4, trim(line))
         end if
      end associate
      write (line, '(a,3(g0.8,a))') 'DELETE ANN ', xc, ' ', yc, ' 0 ', rt
      call do(line)
      call check_blocks(s%model%geometry, 1.0e-9_wp, error)
      if (allocated(error)) call fail(2, 'after DELETE ANN: '//error%message)
      ! the blocks left around the opening that the ring made (new ids) or
      ! changed (another area)
      mean = geometry_total_area(s%model%geometry)/real(geometry_live_blocks(s%model%geometry), wp)
      amin = huge(1.0_wp)
      do b = 1, s%model%geometry%blocks%n
         if (.not. s%model%geometry%blocks%live(b)) cycle
         if (b <= size(area0)) then
            if (s%model%geometry%blocks%area(b) == area0(b)) cycle
         end if
         amin = min(amin, s%model%geometry%blocks%area(b))
      end do
      worst = min(worst, amin/mean)
      if (amin < small_fraction*mean) then
         write (line, '(a,es10.3,a,es10.3)') 'ring block of ', amin, ' m2, mean ', mean
         call fail(3, trim(line))
      end if
      if (s%nerrors > 0) call fail(5, 'a command failed')
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

end program test_stability_rings
