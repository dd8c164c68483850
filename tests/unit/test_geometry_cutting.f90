!> BLOCK / SPLIT / CRACK / DELETE / ROUND / EDGE on small known geometries.
program test_geometry_cutting
   use core_kinds, only: wp, ip
   use core_error, only: error_t
   use model_geometry, only: geometry_t, geometry_init, geometry_live_blocks, cut_touch, &
                             geometry_refused_cuts, &
                             geometry_total_area
   use geometry_cutting, only: cut_create_block, cut_create_circular, cut_split, cut_crack, &
                              cut_remove_partial, cut_delete_range, cut_delete_block, &
                              cut_set_round, cut_set_edge
   use geometry_joint_sets, only: joint_region, joint_set
   use testing, only: check, check_close, check_equal, testing_finish
   implicit none

   call test_tutorial()
   call test_block_errors()
   call test_problem_d()
   call test_partial_cracks()
   call test_delete()
   call test_round_edge()
   call test_jregion()
   call test_material_kept_on_growth()
   call testing_finish()

contains

   !> Area of the live block whose centroid is nearest (x, y).
   function area_near(geo, x, y) result(a)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: x, y
      real(wp) :: a, d, dbest
      integer(ip) :: b
      dbest = huge(1.0_wp)
      a = -1.0_wp
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         d = hypot(geo%blocks%xc(b) - x, geo%blocks%yc(b) - y)
         if (d < dbest) then
            dbest = d
            a = geo%blocks%area(b)
         end if
      end do
   end function area_near

   subroutine test_tutorial()
      type(geometry_t) :: geo
      type(error_t), allocatable :: error
      call geometry_init(geo)
      call cut_create_block(geo, [0.0_wp, 0.0_wp, 20.0_wp, 20.0_wp], &
                            [0.0_wp, 20.0_wp, 20.0_wp, 0.0_wp], 1, 1, error)
      call check(.not. allocated(error), 'tutorial: block created')
      call cut_split(geo, 0.0_wp, 2.0_wp, 20.0_wp, 8.0_wp, error)
      call cut_split(geo, 5.0_wp, 3.0_wp, 5.0_wp, 20.0_wp, error)
      call cut_split(geo, 5.0_wp, 12.0_wp, 20.0_wp, 18.0_wp, error)
      call check_equal(geometry_live_blocks(geo), 4, 'tutorial: 4 blocks')
      call check_close(geometry_total_area(geo), 400.0_wp, 1.0e-12_wp, 'tutorial: total area')
      call check_close(area_near(geo, 10.0_wp, 2.0_wp), 100.0_wp, 1.0e-12_wp, 'lower block')
      call check_close(area_near(geo, 2.5_wp, 12.0_wp), 86.25_wp, 1.0e-12_wp, 'upper left')
      call check_close(area_near(geo, 12.5_wp, 18.5_wp), 75.0_wp, 1.0e-12_wp, 'top right')
      call check_close(area_near(geo, 12.5_wp, 11.0_wp), 138.75_wp, 1.0e-12_wp, 'middle right')
   end subroutine test_tutorial

   subroutine test_block_errors()
      type(geometry_t) :: geo
      type(error_t), allocatable :: error
      call geometry_init(geo)
      call cut_create_block(geo, [0.0_wp, 20.0_wp, 20.0_wp, 0.0_wp], &
                            [0.0_wp, 0.0_wp, 20.0_wp, 20.0_wp], 1, 1, error)
      call check(allocated(error), 'counter-clockwise block refused')
      call cut_create_block(geo, [0.0_wp, 1.0_wp], [0.0_wp, 1.0_wp], 1, 1, error)
      call check(allocated(error), 'two-corner block refused')
      call cut_create_block(geo, [0.0_wp, 10.0_wp, 0.0_wp, 10.0_wp], &
                            [0.0_wp, 10.0_wp, 10.0_wp, 0.0_wp], 1, 1, error)
      call check(allocated(error), 'self-intersecting block refused')
      call cut_split(geo, 0.0_wp, 0.0_wp, 1.0_wp, 1.0_wp, error)
      call check(allocated(error), 'split before block refused')
      call cut_create_circular(geo, 0.0_wp, 0.0_wp, 5.0_wp, 24, 2, 1, error)
      call check(.not. allocated(error), 'circular block created')
      call check_equal(geo%blocks%ncorner(1), 24, 'circular block corners')
      call check_equal(geo%blocks%material(1), 2, 'circular block material')
      call check_close(geo%blocks%area(1), 0.5_wp*24*25.0_wp*sin(2.0_wp*acos(-1.0_wp)/24), &
                       1.0e-12_wp, 'circular block area')
      call cut_create_block(geo, [0.0_wp, 0.0_wp, 1.0_wp], [0.0_wp, 1.0_wp, 0.0_wp], 1, 1, error)
      call check(allocated(error), 'second BLOCK refused')
   end subroutine test_block_errors

   !> Appendix A, verification test D: 4 + 4 orthogonal splits, 25 blocks.
   subroutine test_problem_d()
      type(geometry_t) :: geo
      type(error_t), allocatable :: error
      integer(ip) :: i
      real(wp) :: xs(4) = [2.3_wp, 4.6_wp, 6.9_wp, 9.2_wp]
      call geometry_init(geo)
      call cut_set_round(geo, 0.01_wp, error)
      call cut_create_block(geo, [0.0_wp, 0.0_wp, 11.5_wp, 11.5_wp], &
                            [0.0_wp, 10.0_wp, 10.0_wp, 0.0_wp], 1, 1, error)
      do i = 1, 4
         call cut_split(geo, -1.0_wp, 2.0_wp*i, 12.0_wp, 2.0_wp*i, error)
      end do
      do i = 1, 4
         call cut_split(geo, xs(i), 11.0_wp, xs(i), -0.5_wp, error)
      end do
      call check_equal(geometry_live_blocks(geo), 25, 'problem D: 25 blocks')
      call check_close(geometry_total_area(geo), 115.0_wp, 1.0e-12_wp, 'problem D: area')
      call check_close(area_near(geo, 1.0_wp, 1.0_wp), 4.6_wp, 1.0e-12_wp, 'problem D: block')
   end subroutine test_problem_d

   subroutine test_partial_cracks()
      type(geometry_t) :: geo
      type(error_t), allocatable :: error
      call geometry_init(geo)
      call cut_set_round(geo, 0.05_wp, error)
      call cut_create_block(geo, [0.0_wp, 0.0_wp, 10.0_wp, 10.0_wp], &
                            [0.0_wp, 10.0_wp, 10.0_wp, 0.0_wp], 1, 1, error)
      ! from the left edge to the middle: partial, no new block
      call cut_crack(geo, -1.0_wp, 5.0_wp, 5.0_wp, 5.0_wp, .false., error)
      call check_equal(geometry_live_blocks(geo), 1, 'partial crack keeps one block')
      call check_equal(geo%pending%n, 1, 'partial crack pending')
      ! a bent continuation to the top completes the separation
      call cut_crack(geo, 5.0_wp, 5.0_wp, 7.0_wp, 11.0_wp, .false., error)
      call check_equal(geometry_live_blocks(geo), 2, 'two cracks complete a split')
      call check_close(geometry_total_area(geo), 100.0_wp, 1.0e-12_wp, 'area after crack')
      call check_close(area_near(geo, 2.0_wp, 8.0_wp), 25.0_wp + 25.0_wp/6.0_wp, 1.0e-12_wp, &
                       'cracked corner block area')
      ! a floating crack inside the lower block is removed by JDELETE
      call cut_crack(geo, 2.0_wp, 2.0_wp, 4.0_wp, 3.0_wp, .false., error)
      call check_equal(geometry_live_blocks(geo), 2, 'floating crack keeps blocks')
      call cut_remove_partial(geo)
      call check_equal(geo%pending%n, 0, 'partial cracks removed')
      ! crossing partial cracks: an X from two edges forms a path
      call cut_crack(geo, 10.5_wp, 1.0_wp, 6.0_wp, 3.0_wp, .false., error)
      call cut_crack(geo, 7.0_wp, 4.0_wp, 8.0_wp, -1.0_wp, .false., error)
      call check_equal(geometry_live_blocks(geo), 3, 'crossing partial cracks split')
      call check_close(geometry_total_area(geo), 100.0_wp, 1.0e-12_wp, 'area after X cracks')
   end subroutine test_partial_cracks

   subroutine test_delete()
      type(geometry_t) :: geo
      type(error_t), allocatable :: error
      integer(ip) :: nd
      call geometry_init(geo)
      call cut_set_round(geo, 0.05_wp, error)
      call cut_create_block(geo, [0.0_wp, 0.0_wp, 10.0_wp, 10.0_wp], &
                            [0.0_wp, 10.0_wp, 10.0_wp, 0.0_wp], 1, 1, error)
      call cut_split(geo, 5.0_wp, -1.0_wp, 5.0_wp, 11.0_wp, error)
      call cut_split(geo, -1.0_wp, 5.0_wp, 11.0_wp, 5.0_wp, error)
      call check_equal(geometry_live_blocks(geo), 4, 'delete: 4 blocks')
      call cut_delete_range(geo, 0.0_wp, 5.0_wp, 0.0_wp, 5.0_wp, nd)
      call check_equal(nd, 1, 'delete range: one block')
      call cut_delete_range(geo, 0.0_wp, 10.0_wp, 0.0_wp, 10.0_wp, nd, armin=10.0_wp)
      call check_equal(nd, 0, 'delete range: area threshold keeps blocks')
      call cut_delete_block(geo, 1, error)
      call check(.not. allocated(error), 'delete block 1')
      call cut_delete_block(geo, 1, error)
      call check(allocated(error), 'delete dead block refused')
      call cut_delete_block(geo, 99, error)
      call check(allocated(error), 'delete unknown block refused')
      call check_equal(geometry_live_blocks(geo), 2, 'delete: 2 left')
      call check_close(geometry_total_area(geo) + geo%deleted_area, 100.0_wp, 1.0e-12_wp, &
                       'deleted area accounted')
   end subroutine test_delete

   subroutine test_round_edge()
      type(geometry_t) :: geo
      type(error_t), allocatable :: error
      call geometry_init(geo)
      call check_close(geo%round, 0.5_wp, 0.0_wp, 'default round')
      call check_close(geo%edge_min, 1.0_wp, 0.0_wp, 'default edge')
      call cut_set_round(geo, 0.1_wp, error)
      call check_close(geo%edge_min, 0.2_wp, 1.0e-15_wp, 'edge follows round')
      call cut_set_edge(geo, 0.1_wp, error)
      call check(allocated(error), 'edge < 2 round refused')
      call cut_set_edge(geo, 0.5_wp, error)
      call check(.not. allocated(error), 'edge accepted')
      call cut_create_block(geo, [0.0_wp, 0.0_wp, 10.0_wp, 10.0_wp], &
                            [0.0_wp, 10.0_wp, 10.0_wp, 0.0_wp], 1, 1, error)
      ! a cut 0.3 from the corner on the top edge snaps to the corner
      call cut_split(geo, 0.3_wp, 11.0_wp, 0.3_wp, -1.0_wp, error)
      call check_equal(geometry_live_blocks(geo), 1, 'cut within emin of an edge moved onto it')
      call check(geo%cut_stats(cut_touch) > 0, 'counted as a cut along an existing edge')
      call check_equal(geometry_refused_cuts(geo), 0, 'not counted as refused')
      ! 90-degree corner: rounding circle centre at (d, d) from the corner
      call check_close(geo%corners%radius(1), 0.1_wp, 1.0e-12_wp, 'rounding radius')
      call check_close(geo%corners%rx(1), 0.1_wp, 1.0e-12_wp, 'rounding centre x')
      call check_close(geo%corners%ry(1), 0.1_wp, 1.0e-12_wp, 'rounding centre y')
   end subroutine test_round_edge

   subroutine test_jregion()
      type(geometry_t) :: geo
      type(error_t), allocatable :: error
      call geometry_init(geo)
      call cut_set_round(geo, 0.05_wp, error)
      call cut_create_block(geo, [0.0_wp, 0.0_wp, 10.0_wp, 10.0_wp], &
                            [0.0_wp, 10.0_wp, 10.0_wp, 0.0_wp], 1, 1, error)
      call cut_crack(geo, -1.0_wp, 5.0_wp, 11.0_wp, 5.0_wp, .true., error)
      call check(allocated(error), 'CRACK JREG without JREGION refused')
      call joint_region(geo, [0.0_wp, 10.0_wp, 10.0_wp, 0.0_wp], &
                        [0.0_wp, 0.0_wp, 5.0_wp, 5.0_wp], error)
      call check(allocated(error), 'counter-clockwise JREGION refused')
      call joint_region(geo, [-1.0_wp, -1.0_wp, 11.0_wp, 11.0_wp], &
                        [-1.0_wp, 5.0_wp, 5.0_wp, -1.0_wp], error)
      call check(.not. allocated(error), 'JREGION accepted')
      ! limited to the region: the vertical crack stops at y = 5 (partial)
      call cut_crack(geo, 5.0_wp, -1.0_wp, 5.0_wp, 11.0_wp, .true., error)
      call check_equal(geometry_live_blocks(geo), 1, 'crack limited to JREGION stays partial')
      ! a horizontal JSET inside the region only
      call joint_set(geo, [0.0_wp, 0.0_wp], [100.0_wp, 0.0_wp], [0.0_wp, 0.0_wp], &
                     [2.0_wp, 0.0_wp], error, origin=[0.0_wp, 1.0_wp])
      call check(.not. allocated(error), 'JSET accepted')
      ! joints at y = 1, 3 split; the vertical partial crack then splits the strips
      call check_close(maxval(geo%blocks%area(1:geo%blocks%n), &
                              mask=geo%blocks%live(1:geo%blocks%n)), 70.0_wp, 1.0e-12_wp, &
                       'area above the region untouched')
      call joint_set(geo, [0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp], [0.0_wp, 0.0_wp], &
                     [0.0_wp, 0.0_wp], error)
      call check(allocated(error), 'JSET with zero spacing refused')
   end subroutine test_jregion

   !> Every piece of a cut inherits the material and constitutive number of
   !> the block it was cut from, also when the cut makes the block list grow
   !> (64 -> 128 -> 256 entries): regression for a new block that took its
   !> material from the list being reallocated under it (garbage material
   !> for blocks 65, 129, ...). Reference: BLOCK with material 3, cons 2;
   !> exact integers.
   subroutine test_material_kept_on_growth()
      type(geometry_t) :: geo
      type(error_t), allocatable :: error
      integer(ip) :: b, nbad
      call geometry_init(geo)
      call cut_set_round(geo, 0.01_wp, error)
      call cut_create_block(geo, [0.0_wp, 0.0_wp, 20.0_wp, 20.0_wp], &
                            [0.0_wp, 20.0_wp, 20.0_wp, 0.0_wp], 3, 2, error)
      call joint_set(geo, [0.0_wp, 0.0_wp], [200.0_wp, 0.0_wp], [0.0_wp, 0.0_wp], &
                     [1.0_wp, 0.0_wp], error)
      call joint_set(geo, [90.0_wp, 0.0_wp], [200.0_wp, 0.0_wp], [0.0_wp, 0.0_wp], &
                     [1.0_wp, 0.0_wp], error)
      call check(geometry_live_blocks(geo) >= 300, 'growth: the joint sets make >= 300 blocks')
      nbad = 0
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         if (geo%blocks%material(b) /= 3 .or. geo%blocks%cons(b) /= 2) nbad = nbad + 1
      end do
      call check_equal(nbad, 0, 'growth: every piece keeps material 3 and cons 2')
   end subroutine test_material_kept_on_growth

end program test_geometry_cutting
