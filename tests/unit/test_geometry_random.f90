!> Random SPLIT / CRACK / JSET / TUNNEL / ARC / DELETE patterns over many
!> seeds, checked against the geometry invariants; robustness cases (cuts
!> within round-off of corners and edges, collinear cuts, a cut along a
!> joint); a JSET making more than 10,000 blocks; reproducibility by seed.
program test_geometry_random
   use core_kinds, only: wp, ip, i8
   use core_error, only: error_t
   use model_geometry, only: geometry_t, geometry_init, geometry_set_seed, geometry_random, &
                             geometry_live_blocks, geometry_total_area, geometry_refused_cuts
   use geometry_cutting, only: cut_create_block, cut_split, cut_crack, cut_set_round, &
                              cut_delete_range, cut_remove_partial
   use geometry_joint_sets, only: joint_region, joint_set, joint_tunnel, joint_arc
   use contact_detection, only: contact_rebuild
   use contact_domains, only: domain_rebuild
   use contact_checks, only: check_blocks, check_contacts, check_domains
   use testing, only: check, check_close, check_equal, testing_finish
   implicit none

   integer(ip), parameter :: nseed = 300
   integer(ip) :: seed, nfail, nblocks_total, nrefused_total
   type(geometry_t) :: rng     ! draws the random commands (not the model's generator)

   nfail = 0
   nblocks_total = 0
   nrefused_total = 0
   do seed = 1, nseed
      call random_case(int(seed, i8), nfail)
   end do
   call check_equal(nfail, 0, 'random cases violating an invariant')
   print '(a,f8.1,a,f8.2)', 'random cases: mean blocks ', real(nblocks_total)/nseed, &
      ', mean refused cuts ', real(nrefused_total)/nseed
   call check(nblocks_total > 8*nseed, 'random cases make many blocks')
   call test_reproducible()
   call test_robust_cuts()
   call test_tunnel_arc()
   call test_large_jset()
   call testing_finish()

contains

   !> Invariants after a random sequence of geometry commands.
   subroutine random_case(s, nfail)
      integer(i8), intent(in) :: s
      integer(ip), intent(inout) :: nfail
      type(geometry_t) :: geo
      type(error_t), allocatable :: error
      integer(ip) :: k, nd
      real(wp) :: x1, y1, x2, y2
      call geometry_init(geo)
      call geometry_init(rng)
      call geometry_set_seed(geo, s)
      call geometry_set_seed(rng, s + 1000_i8)
      call cut_set_round(geo, 0.05_wp, error)
      call cut_create_block(geo, [0.0_wp, 0.0_wp, 8.0_wp, 20.0_wp, 20.0_wp], &
                            [0.0_wp, 15.0_wp, 20.0_wp, 18.0_wp, 0.0_wp], 1, 1, error)
      do k = 1, 3
         call segment(x1, y1, x2, y2)
         call cut_split(geo, x1, y1, x2, y2, error)
      end do
      if (r() < 0.5_wp) then
         call joint_region(geo, [2.0_wp, 4.0_wp, 18.0_wp, 16.0_wp], &
                           [2.0_wp, 17.0_wp, 16.0_wp, 3.0_wp], error)
      end if
      x1 = 180.0_wp*r()
      call joint_set(geo, [x1, 10.0_wp], [3.0_wp + 10.0_wp*r(), 1.0_wp], &
                     [1.0_wp*r(), 0.5_wp*r()], [2.0_wp + 3.0_wp*r(), 0.5_wp], error)
      call joint_set(geo, [x1 + 40.0_wp + 100.0_wp*r(), 10.0_wp], [3.0_wp + 10.0_wp*r(), 1.0_wp], &
                     [1.0_wp*r(), 0.5_wp*r()], [2.0_wp + 3.0_wp*r(), 0.5_wp], error)
      if (r() < 0.5_wp) call joint_tunnel(geo, 4.0_wp + 12.0_wp*r(), 4.0_wp + 10.0_wp*r(), &
                                          1.0_wp + 2.0_wp*r(), 12, error)
      do k = 1, 4
         call segment(x1, y1, x2, y2)
         call cut_crack(geo, x1, y1, x2, y2, .false., error)
      end do
      do k = 1, 2
         call segment(x1, y1, x2, y2)
         call cut_split(geo, x1, y1, x2, y2, error)
      end do
      call cut_remove_partial(geo)
      x1 = 20.0_wp*r()
      y1 = 20.0_wp*r()
      call cut_delete_range(geo, x1, x1 + 3.0_wp, y1, y1 + 3.0_wp, nd)
      call contact_rebuild(geo)
      call domain_rebuild(geo)
      nblocks_total = nblocks_total + geometry_live_blocks(geo)
      nrefused_total = nrefused_total + geometry_refused_cuts(geo)
      call check_blocks(geo, 1.0e-9_wp, error)
      if (.not. allocated(error)) call check_contacts(geo, error)
      if (.not. allocated(error)) call check_domains(geo, error)
      if (allocated(error)) then
         nfail = nfail + 1
         print '(a,i0,a)', 'seed ', s, ': '//error%message
      end if
   end subroutine random_case

   real(wp) function r()
      r = geometry_random(rng)
   end function r

   subroutine segment(ax, ay, bx, by)
      real(wp), intent(out) :: ax, ay, bx, by
      ax = -2.0_wp + 24.0_wp*r()
      ay = -2.0_wp + 24.0_wp*r()
      bx = -2.0_wp + 24.0_wp*r()
      by = -2.0_wp + 24.0_wp*r()
   end subroutine segment

   subroutine jointed(geo, s)
      type(geometry_t), intent(inout) :: geo
      integer(i8), intent(in) :: s
      type(error_t), allocatable :: error
      call geometry_init(geo)
      call geometry_set_seed(geo, s)
      call cut_set_round(geo, 0.05_wp, error)
      call cut_create_block(geo, [0.0_wp, 0.0_wp, 20.0_wp, 20.0_wp], &
                            [0.0_wp, 20.0_wp, 20.0_wp, 0.0_wp], 1, 1, error)
      call joint_set(geo, [30.0_wp, 10.0_wp], [6.0_wp, 2.0_wp], [1.0_wp, 0.5_wp], &
                     [2.0_wp, 0.5_wp], error)
      call joint_set(geo, [-60.0_wp, 10.0_wp], [6.0_wp, 2.0_wp], [1.0_wp, 0.5_wp], &
                     [2.0_wp, 0.5_wp], error)
   end subroutine jointed

   subroutine test_reproducible()
      type(geometry_t) :: a, b, c
      integer(ip) :: n
      logical :: same
      call jointed(a, 7_i8)
      call jointed(b, 7_i8)
      call jointed(c, 8_i8)
      n = a%corners%n
      call check(geometry_live_blocks(a) > 20, 'jointed model has many blocks')
      same = a%blocks%n == b%blocks%n .and. n == b%corners%n
      if (same) same = all(a%corners%x(1:n) == b%corners%x(1:n)) .and. &
                       all(a%corners%y(1:n) == b%corners%y(1:n))
      call check(same, 'same seed gives identical blocks')
      same = a%corners%n == c%corners%n
      if (same) same = all(a%corners%x(1:n) == c%corners%x(1:n))
      call check(.not. same, 'another seed gives other blocks')
   end subroutine test_reproducible

   subroutine robust_grid(geo)
      type(geometry_t), intent(inout) :: geo
      type(error_t), allocatable :: error
      integer(ip) :: i
      call geometry_init(geo)
      call cut_set_round(geo, 0.05_wp, error)
      call cut_create_block(geo, [0.0_wp, 0.0_wp, 10.0_wp, 10.0_wp], &
                            [0.0_wp, 10.0_wp, 10.0_wp, 0.0_wp], 1, 1, error)
      do i = 1, 4
         call cut_split(geo, -1.0_wp, 2.0_wp*i, 11.0_wp, 2.0_wp*i, error)
         call cut_split(geo, 2.0_wp*i, -1.0_wp, 2.0_wp*i, 11.0_wp, error)
      end do
   end subroutine robust_grid

   subroutine test_robust_cuts()
      type(geometry_t) :: geo
      type(error_t), allocatable :: error
      call robust_grid(geo)
      call check_equal(geometry_live_blocks(geo), 25, 'robust: grid')
      ! along existing joints, within round-off of them, and along the boundary
      call cut_split(geo, -1.0_wp, 4.0_wp, 11.0_wp, 4.0_wp, error)
      call cut_split(geo, -1.0_wp, 6.0_wp + 1.0e-13_wp, 11.0_wp, 6.0_wp - 1.0e-13_wp, error)
      call cut_split(geo, 4.0_wp + 1.0e-12_wp, -1.0_wp, 4.0_wp, 11.0_wp, error)
      call cut_split(geo, 0.0_wp, -1.0_wp, 0.0_wp, 11.0_wp, error)
      call cut_split(geo, 10.0_wp, 12.0_wp, 10.0_wp, -2.0_wp, error)
      call cut_crack(geo, 2.0_wp, 0.5_wp, 2.0_wp, 9.5_wp, .false., error)
      call check_equal(geometry_live_blocks(geo), 25, 'robust: cuts along joints add nothing')
      ! through grid nodes exactly, and within round-off of a corner
      call cut_split(geo, -1.0_wp, -1.0_wp, 11.0_wp, 11.0_wp, error)
      call check_equal(geometry_live_blocks(geo), 30, 'robust: diagonal through nodes')
      call cut_split(geo, 1.0e-13_wp, 10.0_wp, 10.0_wp, 1.0e-13_wp, error)
      ! four grid blocks and both halves of the centre block
      call check_equal(geometry_live_blocks(geo), 36, 'robust: anti-diagonal near corners')
      ! collinear overlapping cracks
      call cut_crack(geo, 1.0_wp, 3.0_wp, 1.0_wp, 3.5_wp, .false., error)
      call cut_crack(geo, 1.0_wp, 3.2_wp, 1.0_wp, 3.8_wp, .false., error)
      call cut_remove_partial(geo)
      call contact_rebuild(geo)
      call domain_rebuild(geo)
      call check_blocks(geo, 1.0e-12_wp, error)
      call check(.not. allocated(error), 'robust: blocks')
      call check_contacts(geo, error)
      call check(.not. allocated(error), 'robust: contacts')
      call check_domains(geo, error)
      call check(.not. allocated(error), 'robust: domains')
   end subroutine test_robust_cuts

   subroutine test_tunnel_arc()
      type(geometry_t) :: geo
      type(error_t), allocatable :: error
      integer(ip) :: nd, before
      call robust_grid(geo)
      ! the ring crosses joints, so each arc between joints separates
      call joint_tunnel(geo, 5.0_wp, 5.0_wp, 3.0_wp, 16, error)
      call check(.not. allocated(error), 'tunnel accepted')
      call check(geometry_live_blocks(geo) > 25, 'tunnel cuts blocks')
      call cut_remove_partial(geo)
      before = geometry_live_blocks(geo)
      ! a crack through the tunnel stops at its periphery: interior unchanged
      call cut_crack(geo, 5.0_wp, -1.0_wp, 5.0_wp, 11.0_wp, .false., error)
      call cut_delete_range(geo, 2.5_wp, 7.5_wp, 2.5_wp, 7.5_wp, nd)
      call check(nd >= 4, 'tunnel interior blocks deleted')
      call contact_rebuild(geo)
      call domain_rebuild(geo)
      call check_blocks(geo, 1.0e-12_wp, error)
      call check(.not. allocated(error), 'tunnel: blocks')
      call check_domains(geo, error)
      call check(.not. allocated(error), 'tunnel: domains')
      ! the excavation is one void with the area of the deleted blocks
      call check_close(maxval(geo%domains%area(1:geo%domains%n)), geo%deleted_area, &
                       1.0e-9_wp, 'tunnel void area')
      call check(geometry_live_blocks(geo) >= before - nd, 'tunnel: crack stopped at ring')
      ! ARC across the grid
      call robust_grid(geo)
      call joint_arc(geo, 0.0_wp, 0.0_wp, 7.0_wp, 0.0_wp, 90.0_wp, 12, error)
      call check(.not. allocated(error), 'arc accepted')
      call check(geometry_live_blocks(geo) > 25, 'arc cuts blocks')
      call check_close(geometry_total_area(geo), 100.0_wp, 1.0e-12_wp, 'arc keeps area')
   end subroutine test_tunnel_arc

   subroutine test_large_jset()
      type(geometry_t) :: geo
      type(error_t), allocatable :: error
      integer(ip) :: n
      call geometry_init(geo)
      call cut_set_round(geo, 0.01_wp, error)
      call cut_create_block(geo, [0.0_wp, 0.0_wp, 100.0_wp, 100.0_wp], &
                            [0.0_wp, 100.0_wp, 100.0_wp, 0.0_wp], 1, 1, error)
      call joint_set(geo, [0.0_wp, 0.0_wp], [1000.0_wp, 0.0_wp], [0.0_wp, 0.0_wp], &
                     [0.95_wp, 0.0_wp], error, origin=[0.5_wp, 0.5_wp])
      call joint_set(geo, [90.0_wp, 0.0_wp], [1000.0_wp, 0.0_wp], [0.0_wp, 0.0_wp], &
                     [0.95_wp, 0.0_wp], error, origin=[0.5_wp, 0.5_wp])
      n = geometry_live_blocks(geo)
      call check(n > 10000, 'large JSET: more than 10,000 blocks')
      call check_close(geometry_total_area(geo), 1.0e4_wp, 1.0e-9_wp, 'large JSET: area')
      call contact_rebuild(geo)
      call domain_rebuild(geo)
      call check_domains(geo, error)
      call check(.not. allocated(error), 'large JSET: domains')
      call check(geo%contacts%n > 4*n, 'large JSET: contacts')
   end subroutine test_large_jset

end program test_geometry_random
