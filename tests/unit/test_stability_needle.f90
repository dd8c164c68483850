!> A thin block beside a sharp corner of another block (stability): the
!> contact scan must not give the corner a contact with the thin block's
!> far edge.
!>
!> The two blocks are blocks 485 and 923 of a user's 40 m tunnel model
!> (ROUND 0.05, TUNNEL r = 3 with 18 sides, two joint sets) at cycle 114200,
!> coordinates as PRINT CORNER gave them (6 digits). Block 923 is a needle
!> 1 cm across at its tip, the sliver between the TUNNEL wall and a joint;
!> block 485's corner at (2.92792, -0.854339) has a 25.6 degree wedge and
!> rounding radius 0.0114, its circle centre about 5 cm down the wedge's
!> bisector at (2.909, -0.901). That centre lies OUTSIDE the needle, 1.7 cm
!> to the right of its right edge, over the needle's rounded tip (whose
!> straight edges end 5 cm from the tip vertex), so no feature of the
!> needle faces it; but it lies 3.3 cm + radius behind the needle's LEFT
!> edge, within the contact margin (0.05). Before the fix the scan gave the
!> corner a contact with that left edge, overlap 3.27 cm, and the next step
!> stopped the run with "Contact Overlap Too Great" (limit 0.025).
!> Reference: hand geometry above; the only contact the two blocks have is
!> the needle's rounded tip against block 485's upper edge, a gap of
!> 2.5 mm as PRINT CONTACT DISP showed it in the full model (gap > 0).
program test_stability_needle
   use core_kinds, only: wp, ip
   use core_error, only: error_t
   use model_geometry, only: geometry_t, geometry_init
   use geometry_cutting, only: cut_set_round
   use geometry_blocks, only: geometry_add_block
   use contact_refresh, only: geometry_refresh
   use contact_update, only: contact_scan, contact_margin
   use contact_kinematics, only: contact_geometry
   use testing, only: check, check_equal, testing_finish
   implicit none

   type(geometry_t) :: geo
   type(error_t), allocatable :: error
   integer(ip) :: id, nnew, nbroken, c, nlive
   real(wp) :: gap, nx, ny, px, py, worst

   call geometry_init(geo)
   call cut_set_round(geo, 0.05_wp, error)
   call check(.not. allocated(error), 'needle: ROUND 0.05')
   geo%extent = 40.0_wp
   geo%tol = 1.0e-9_wp*geo%extent
   ! block 485 (clockwise, as its corner ring runs)
   call geometry_add_block(geo, [2.92792_wp, 2.70395_wp, 1.87973_wp, 2.28220_wp, 2.80273_wp], &
                           [-0.854339_wp, -2.21678_wp, -2.27335_wp, -1.93532_wp, -1.03278_wp], &
                           1_ip, 1_ip, id)
   ! block 923, the needle: tip at (2.88219, -0.949574)
   call geometry_add_block(geo, [2.92833_wp, 3.11732_wp, 2.94672_wp, 2.88219_wp, 2.96950_wp], &
                           [0.193759_wp, 0.205657_wp, -0.632533_wp, -0.949574_wp, -0.104567_wp], &
                           1_ip, 1_ip, id)
   call geometry_refresh(geo)
   geo%mechanical = .true.
   call check(abs(geo%corners%radius(geo%blocks%first_corner(1)) - 0.0114_wp) < 1.0e-4_wp, &
              'needle: block 485 corner radius 0.0114 as in the model')
   call contact_scan(geo, contact_margin(geo), nnew, nbroken)
   worst = huge(1.0_wp)
   nlive = 0
   do c = 1, geo%contacts%n
      if (.not. geo%contacts%live(c)) cycle
      nlive = nlive + 1
      call contact_geometry(geo, c, 1.0e-3_wp*contact_margin(geo), gap, nx, ny, px, py)
      worst = min(worst, gap)
   end do
   call check(nlive >= 1, 'needle: the tip touches block 485')
   ! no overlap at all: the blocks are apart (smallest gap 2.5 mm)
   call check(worst > 0.0_wp, 'needle: no contact starts overlapping (smallest gap > 0)')
   call check(worst < 5.0e-3_wp, 'needle: the tip contact (gap 2.5 mm) is there')
   call check_equal(int(nlive), 1, 'needle: one contact, the tip against the upper edge')
   call testing_finish()
end program test_stability_needle
