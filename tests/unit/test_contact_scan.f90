!> Contacts at joint ends and T-junctions (verification B): the normal a
!> contact gets when contacts are rebuilt, no second contact where two
!> rounded corners already make one, and contact lengths that add up to the
!> shared stretch of the unrounded blocks after a scan.
!> References are hand geometry stated next to each check; tolerance 1e-12
!> (round-off of a few operations) unless said otherwise.
program test_contact_scan
   use core_kinds, only: wp, ip
   use core_error, only: error_t
   use model_geometry, only: contact_corner1, contact_corner2
   use model_geometry, only: geometry_t, geometry_init, geometry_add_contact
   use geometry_cutting, only: cut_create_block, cut_split, cut_set_round
   use contact_refresh, only: geometry_refresh
   use contact_update, only: contact_scan, contact_margin
   use contact_kinematics, only: contact_overlap_limit, switch_fraction
   use commands_session, only: session_t, session_init, session_execute_line
   use testing, only: check, check_close, check_equal, testing_finish
   use testing_session, only: session_new_quiet, session_lines
   implicit none

   real(wp), parameter :: tol = 1.0e-12_wp

   call test_scan_lengths()
   call test_joint_end_no_duplicate()
   call test_tjunction_normals()
   call test_initial_jmat()
   call test_twins_dropped()
   call test_wedge_tips_passing(1.0e-4_wp)
   call test_wedge_tips_passing(-1.0e-4_wp)
   call test_xcrossing_limit()
   call testing_finish()

contains

   !> Two unit squares on top of each other (ROUND 0.01): one horizontal
   !> joint of length 1 from x = 0 to 1 at y = 1.
   subroutine two_blocks(geo)
      type(geometry_t), intent(inout) :: geo
      type(error_t), allocatable :: error
      call geometry_init(geo)
      call cut_set_round(geo, 0.01_wp, error)
      call cut_create_block(geo, [0.0_wp, 0.0_wp, 1.0_wp, 1.0_wp], &
                            [0.0_wp, 2.0_wp, 2.0_wp, 0.0_wp], 1, 1, error)
      call cut_split(geo, -1.0_wp, 1.0_wp, 2.0_wp, 1.0_wp, error)
      call check(.not. allocated(error), 'two blocks: split')
      call geometry_refresh(geo)
      geo%mechanical = .true.
   end subroutine two_blocks

   !> Manual 4.5 CHANGE: "All contacts initially default to JMAT=1" (SET
   !> JMATDF: the block material is the default for contacts made after
   !> cycle 1 only). Two blocks of material 3 give contacts of JMAT 1.
   subroutine test_initial_jmat()
      type(geometry_t) :: geo
      type(error_t), allocatable :: error
      integer(ip) :: c
      call geometry_init(geo)
      call cut_set_round(geo, 0.01_wp, error)
      call cut_create_block(geo, [0.0_wp, 0.0_wp, 1.0_wp, 1.0_wp], &
                            [0.0_wp, 2.0_wp, 2.0_wp, 0.0_wp], 3, 1, error)
      call cut_split(geo, -1.0_wp, 1.0_wp, 2.0_wp, 1.0_wp, error)
      call geometry_refresh(geo)
      call check(live_contacts(geo) > 0, 'initial JMAT: contacts made')
      call check(all(geo%blocks%material(1:geo%blocks%n) == 3), 'initial JMAT: blocks are material 3')
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         call check_equal(int(geo%contacts%jmat(c)), 1, 'initial JMAT: contact has JMAT 1')
      end do
   end subroutine test_initial_jmat

   real(wp) function total_length(geo) result(s)
      type(geometry_t), intent(in) :: geo
      integer(ip) :: c
      s = 0.0_wp
      do c = 1, geo%contacts%n
         if (geo%contacts%live(c)) s = s + geo%contacts%length(c)
      end do
   end function total_length

   integer function live_contacts(geo) result(n)
      type(geometry_t), intent(in) :: geo
      n = count(geo%contacts%live(1:geo%contacts%n))
   end function live_contacts

   !> Move the upper block (centroid above y = 1) by (dx, 0): corners and
   !> rounding centres.
   subroutine shift_upper(geo, dx)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: dx
      integer(ip) :: b, c, k
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         if (geo%blocks%yc(b) < 1.0_wp) cycle
         c = geo%blocks%first_corner(b)
         do k = 1, geo%blocks%ncorner(b)
            geo%corners%x(c) = geo%corners%x(c) + dx
            geo%corners%rx(c) = geo%corners%rx(c) + dx
            c = geo%corners%next(c)
         end do
      end do
   end subroutine shift_upper

   !> The two end contacts of the joint each carry half its length after
   !> a scan (Fig 3-3b), as after the rebuild: 0.5 + 0.5 = 1. Measured
   !> between the contact points, which sit a rounding radius (0.01) inside
   !> the block ends, the sum would be 1 - 2 x 0.01 = 0.98.
   subroutine test_scan_lengths()
      type(geometry_t) :: geo
      integer(ip) :: nnew, nbroken, c
      call two_blocks(geo)
      call check_equal(live_contacts(geo), 2, 'joint: 2 contacts after the rebuild')
      call check_close(total_length(geo), 1.0_wp, tol, 'joint: rebuild lengths add up to 1')
      call contact_scan(geo, contact_margin(geo), nnew, nbroken)
      call check_equal(int(nnew), 0, 'joint: scan makes no contact')
      do c = 1, geo%contacts%n
         call check_close(geo%contacts%length(c), 0.5_wp, tol, 'joint: scan length 1/2 each')
      end do
      call check_close(total_length(geo), 1.0_wp, tol, 'joint: scan lengths add up to 1')
   end subroutine test_scan_lengths

   !> The upper block shears by +1e-5 (rounding radius 0.01): the corner-
   !> corner contact at each end of the joint becomes a corner against the
   !> other block's edge (contact_geometry). It shears back by 1.5e-5 to
   !> -0.5e-5, inside the switch hysteresis (1e-3 x margin = 1e-5), so the
   !> contacts keep their kind while the corner they let go now faces the
   !> other block's straight edge part. Still one contact per joint end: no
   !> new contacts, 2 live, lengths still adding up to 1 (a second contact
   !> at an end would start force-free and take half the joint's length).
   subroutine test_joint_end_no_duplicate()
      type(geometry_t) :: geo
      integer(ip) :: nnew, nbroken, c
      logical :: switched
      call two_blocks(geo)
      call contact_scan(geo, contact_margin(geo), nnew, nbroken)
      call shift_upper(geo, 1.0e-5_wp)
      call contact_scan(geo, contact_margin(geo), nnew, nbroken)
      switched = .true.
      do c = 1, geo%contacts%n
         if (geo%contacts%live(c)) switched = switched .and. geo%contacts%kind(c) /= 1
      end do
      call check(switched, 'joint end: sheared corner-corner contacts became corner-edge')
      call check_equal(int(nnew), 0, 'joint end: shear makes no contact')
      call shift_upper(geo, -1.5e-5_wp)
      call contact_scan(geo, contact_margin(geo), nnew, nbroken)
      call check_equal(int(nnew), 0, 'joint end: shear back (hysteresis) makes no contact')
      call check_equal(live_contacts(geo), 2, 'joint end: still one contact per end')
      ! each end contact sits at its own corner and the ends moved by
      ! 0.5e-5: 1 within 1e-4
      call check_close(total_length(geo), 1.0_wp, 1.0e-4_wp, 'joint end: lengths add up to 1')
   end subroutine test_joint_end_no_duplicate

   !> Two FDEF blocks side by side (x < 0.2 and x > 0.2, height 0.2), the
   !> left one split by a horizontal joint at y = 0.1 ending on the vertical
   !> joint: a T-junction at (0.2, 0.1), where the right block has an edge
   !> gridpoint (GEN AUTO 0.08 splits its edges). The corners of the left
   !> blocks there touch the straight edge of the right block: their contact
   !> normals are horizontal, so INSITU STRESS -2e6 0 -5e6 gives every
   !> contact of the vertical joint fn = 2e6 L and fs = 0 (every contact of
   !> the model has an axis-parallel normal and fs = 0). The line of the
   !> circle centres would lean 45 degrees (fn = 3.5e6 L, fs = -1.5e6 L).
   subroutine test_tjunction_normals()
      type(session_t) :: session
      type(error_t), allocatable :: error
      integer(ip) :: c, nvert
      call session_init(session, error)
      session%out%screen = .false.
      call session_execute_line(session, 'ROUND 0.001', 1)
      call session_execute_line(session, 'BLOCK 0,0 0,0.2 0.4,0.2 0.4,0', 1)
      call session_execute_line(session, 'CRACK 0.2,-1 0.2,1', 1)
      call session_execute_line(session, 'CRACK -0.1,0.1 0.2,0.1', 1)
      call session_execute_line(session, 'CHANGE FDEF', 1)
      call session_execute_line(session, 'GEN 0,0.4 0,0.2 AUTO 0.08', 1)
      call session_execute_line(session, &
                                'PROP M=1 D=2850 K=61.8E9 G=35.3E9 JKN=531.9E9 JKS=438.8E9', 1)
      call session_execute_line(session, 'INSITU STRESS -2.0E6 0.0 -5.0E6', 1)
      nvert = 0
      associate (ct => session%model%geometry%contacts, co => session%model%geometry%corners)
         call check(any(abs(co%x(1:co%n) - 0.2_wp) < 1.0e-12_wp .and. &
                        abs(co%y(1:co%n) - 0.1_wp) < 1.0e-12_wp .and. &
                        co%radius(1:co%n) == 0.0_wp), &
                    'T-junction: the right block has a straight corner (gridpoint) at (0.2, 0.1)')
         do c = 1, ct%n
            if (.not. ct%live(c)) cycle
            call check(abs(ct%nx(c)*ct%ny(c)) < tol, 'T-junction: normal parallel to an axis')
            call check(abs(ct%state%fs(c)) <= tol*ct%state%fn(c), 'T-junction: INSITU fs = 0')
            if (abs(ct%x(c) - 0.2_wp) < 1.0e-6_wp .and. abs(ct%ny(c)) < tol .and. &
                ct%length(c) > 0.0_wp) then
               nvert = nvert + 1
               call check_close(ct%state%fn(c), 2.0e6_wp*ct%length(c), tol, &
                                'T-junction: vertical joint fn = 2e6 L')
            end if
         end do
      end associate
      call check(nvert >= 4, 'T-junction: the vertical joint has contacts with length')
   end subroutine test_tjunction_normals


   !> A contact whose feature walk has brought it onto the same corner and
   !> edge of the same blocks as another (made here by copying one) is
   !> dropped at the next scan, the first kept: two joint-end contacts left,
   !> one broken (found as three twins carrying three times the stiffness in
   !> a sheared FDEF model).
   subroutine test_twins_dropped()
      type(geometry_t) :: geo
      integer(ip) :: nnew, nbroken, c, twin, first
      call two_blocks(geo)
      call contact_scan(geo, contact_margin(geo), nnew, nbroken)
      call check_equal(live_contacts(geo), 2, 'twins: two joint-end contacts to start')
      first = 0
      do c = 1, geo%contacts%n
         if (geo%contacts%live(c) .and. first == 0) first = c
      end do
      call geometry_add_contact(geo, twin)
      geo%contacts%block1(twin) = geo%contacts%block1(first)
      geo%contacts%block2(twin) = geo%contacts%block2(first)
      geo%contacts%kind(twin) = geo%contacts%kind(first)
      geo%contacts%end1(twin) = geo%contacts%end1(first)
      geo%contacts%end2(twin) = geo%contacts%end2(first)
      geo%contacts%state%fn(twin) = 1.0_wp
      call check_equal(live_contacts(geo), 3, 'twins: a copy added')
      call contact_scan(geo, contact_margin(geo), nnew, nbroken)
      call check_equal(live_contacts(geo), 2, 'twins: the copy is dropped at the scan')
      call check(logical(geo%contacts%live(first) .and. .not. geo%contacts%live(twin)), &
                 'twins: the first contact is the one kept')
      call check_equal(int(nnew), 0, 'twins: no contact made')
   end subroutine test_twins_dropped

   !> Two opposite wedges of a joint crossing (the joints y = 0 and
   !> y = 0.4 x, the blocks above and below deleted: the new user's tunnel
   !> deck, seed 7): A (x > 0) above y = 0, B (x < 0) below, tip to tip at
   !> the origin. A slides 0.05 along y = 0 past B's tip, so A's lower edge
   !> lies on B's upper edge over [-0.05, 0], and B turns by `turn` rad
   !> about its tip. An edge-edge contact is two corner-edge contacts, one
   !> at each end of the shared stretch (manual Section 3.3, Fig 3-3b): A's
   !> tip on B's edge and B's tip on A's edge, each 0.025 long. A turn of
   !> 1e-4 rad leaves one tip's edge normal just outside the other tip's
   !> arc; with one contact only, the tips took the whole thrust on the
   !> minimum contact length and overlapped until Contact Overlap Too
   !> Great (seed 7, cycle 22518).
   subroutine test_wedge_tips_passing(turn)
      real(wp), intent(in) :: turn
      type(session_t) :: session
      integer(ip) :: nnew, nbroken, a, b, c, k, n, tipa, tipb
      logical :: has_a, has_b
      real(wp) :: x, y
      call session_new_quiet(session)
      call session_lines(session, [character(len=30) :: 'ROUND 0.01', 'BLOCK -1,-1 -1,1 1,1 1,-1', &
                                   'CRACK -1,0 1,0', 'CRACK -1,-0.4 1,0.4', 'DELETE -1,1 0.3,1', &
                                   'DELETE -1,1 -1,-0.3'])
      associate (geo => session%model%geometry)
         call check_equal(int(count(geo%blocks%live(1:geo%blocks%n))), 2, 'wedge tips: two wedges')
         a = 0
         b = 0
         do k = 1, geo%blocks%n
            if (.not. geo%blocks%live(k)) cycle
            if (geo%blocks%xc(k) > 0.0_wp) a = k
            if (geo%blocks%xc(k) < 0.0_wp) b = k
         end do
         tipa = tip(geo, a)
         tipb = tip(geo, b)
         call check(tipa > 0 .and. tipb > 0, 'wedge tips: both tips at the origin')
         c = geo%blocks%first_corner(a)
         do k = 1, geo%blocks%ncorner(a)
            geo%corners%x(c) = geo%corners%x(c) - 0.05_wp
            geo%corners%rx(c) = geo%corners%rx(c) - 0.05_wp
            c = geo%corners%next(c)
         end do
         c = geo%blocks%first_corner(b)
         do k = 1, geo%blocks%ncorner(b)
            x = geo%corners%x(c)
            y = geo%corners%y(c)
            geo%corners%x(c) = x*cos(turn) - y*sin(turn)
            geo%corners%y(c) = x*sin(turn) + y*cos(turn)
            x = geo%corners%rx(c)
            y = geo%corners%ry(c)
            geo%corners%rx(c) = x*cos(turn) - y*sin(turn)
            geo%corners%ry(c) = x*sin(turn) + y*cos(turn)
            c = geo%corners%next(c)
         end do
         call contact_scan(geo, contact_margin(geo), nnew, nbroken)
         n = 0
         has_a = .false.
         has_b = .false.
         do c = 1, geo%contacts%n
            if (.not. geo%contacts%live(c)) cycle
            n = n + 1
            has_a = has_a .or. contact_corner1(geo%contacts, c) == tipa .or. &
                    contact_corner2(geo%contacts, c) == tipa
            has_b = has_b .or. contact_corner1(geo%contacts, c) == tipb .or. &
                    contact_corner2(geo%contacts, c) == tipb
         end do
         call check_equal(int(n), 2, 'wedge tips: two contacts on the shared stretch')
         call check(has_a .and. has_b, 'wedge tips: one at each tip')
         ! each half of the 0.05 stretch, within the turn's 1e-4 x 0.05
         do c = 1, geo%contacts%n
            if (geo%contacts%live(c)) call check_close(geo%contacts%length(c), 0.025_wp, 1.0e-5_wp, &
                                                       'wedge tips: half the stretch each')
         end do
      end associate
   end subroutine test_wedge_tips_passing

   !> Two joints crossing at 30 degrees (y - 5 = +-tan(15 deg) (x - 5),
   !> ROUND d = 0.01): four blocks at (5, 5), the blunt ones (150 degrees,
   !> rounding radius d tan 75 deg = 0.0373) above and below, the 30-degree
   !> wedges left and right. The blunt blocks meet only at their corners:
   !> one corner-corner contact of length 0, its gap the two circles'
   !> 2 d (1 - sin 75) / cos 75 = 2.632e-3 (the rounding cuts the vertices
   !> off; manual Section 3.3, Fig 3-3d). Overlap tolerances
   !> (contact_overlap_limit: half the sum of the radii of the two corners
   !> the contact's normal depends on, at most d and a quarter of the
   !> shortest edge, at most 2 d, never below OVTOL): the diagonal
   !> min(0.0373, 2 d) = 2 d; a joint contact at the crossing, wedge tip
   !> (radius d tan 15 deg = 2.68e-3) against the blunt block's edge at its
   !> blunt end, d (tan 15 + tan 75) / 2 = 2 d; one at the box's side
   !> (radii d tan 37.5 and d tan 52.5 deg) 1.035 d as corner-corner, 0.9
   !> x 2.07 d = 1.863 d as corner-edge (its normal the edge's: session
   !> 42); the wedges' tips
   !> (length 0, 2.68e-3 both) keep OVTOL. SET OVTOL t:
   !> t for every contact. Contacts as a CYCLE's first scan makes them.
   !> Tolerance 1e-12 (the gap: 1e-9, the crack ends given to 1e-9).
   subroutine test_xcrossing_limit()
      type(session_t) :: session
      integer(ip) :: c, diag, b1, b2, nnew, nbroken
      real(wp), parameter :: d = 0.01_wp, ov = 0.5_wp*d
      real(wp) :: r, pi
      pi = acos(-1.0_wp)
      r = d*tan(75.0_wp*pi/180.0_wp)
      call session_new_quiet(session)
      call session_lines(session, [character(len=40) :: 'ROUND 0.01', 'BLOCK 0,0 0,10 10,10 10,0', &
                                   'CRACK 0,3.660254038 10,6.339745962', &
                                   'CRACK 0,6.339745962 10,3.660254038'])
      associate (geo => session%model%geometry)
         call check_equal(int(count(geo%blocks%live(1:geo%blocks%n))), 4, 'X-crossing: four blocks')
         call geometry_refresh(geo)
         call contact_scan(geo, contact_margin(geo), nnew, nbroken)
         diag = 0
         do c = 1, geo%contacts%n
            if (.not. geo%contacts%live(c)) cycle
            b1 = geo%contacts%block1(c)
            b2 = geo%contacts%block2(c)
            if (abs(geo%blocks%yc(b1) - 5.0_wp) > 1.0_wp .and. &
                abs(geo%blocks%yc(b2) - 5.0_wp) > 1.0_wp) then
               diag = c
            else if (geo%contacts%length(c) > 0.0_wp .and. abs(geo%contacts%x(c) - 5.0_wp) < 1.0_wp) then
               call check_close(contact_overlap_limit(geo, c, ov, .false.), 2.0_wp*d, 1.0e-12_wp, &
                                'X-crossing: a joint contact at the crossing may overlap by 2 d')
            else if (geo%contacts%length(c) > 0.0_wp) then
               call check_close(contact_overlap_limit(geo, c, ov, .false.), &
                                merge(0.5_wp, switch_fraction, geo%contacts%kind(c) == 1)*d* &
                                (tan(37.5_wp*pi/180.0_wp) + tan(52.5_wp*pi/180.0_wp)), 1.0e-9_wp, &
                                'X-crossing: a joint contact at the box''s side, d (tan 37.5 + tan 52.5) '// &
                                'x 1/2 (corner-corner) or 0.9 (corner-edge)')
            else
               call check_close(contact_overlap_limit(geo, c, ov, .false.), ov, tol, &
                                'X-crossing: the wedges'' tips keep OVTOL')
            end if
            ! SET OVTOL: the user's limit everywhere
            call check_close(contact_overlap_limit(geo, c, 0.003_wp, .true.), 0.003_wp, tol, &
                             'X-crossing: SET OVTOL 0.003 is every contact''s limit')
            call check_close(contact_overlap_limit(geo, c, 0.03_wp, .true.), 0.03_wp, tol, &
                             'X-crossing: SET OVTOL 0.03 is every contact''s limit')
         end do
         call check(diag > 0, 'X-crossing: the blunt blocks touch at their corners')
         if (diag == 0) return
         call check_equal(int(geo%contacts%kind(diag)), 1, 'X-crossing: diagonal is corner-corner')
         call check_close(geo%contacts%length(diag), 0.0_wp, tol, 'X-crossing: diagonal has length 0')
         call check_close(geo%contacts%gap(diag), &
                          2.0_wp*d*(1.0_wp - sin(75.0_wp*pi/180.0_wp))/cos(75.0_wp*pi/180.0_wp), &
                          1.0e-9_wp, 'X-crossing: diagonal gap of the rounded corners')
         call check_close(contact_overlap_limit(geo, diag, ov, .false.), 2.0_wp*d, tol, &
                          'X-crossing: diagonal tolerance 2 d (radii 0.0373 each)')
         ! the rounding length raised to 0.05 with the radii as they are: the
         ! radius bound (r1 + r2) / 2 = 0.0373 is below d and the edges' quarter
         geo%round = 0.05_wp
         call check_close(contact_overlap_limit(geo, diag, 0.025_wp, .false.), r, 1.0e-9_wp, &
                          'X-crossing: diagonal tolerance capped at (r1 + r2) / 2')
         ! OVTOL above the bounds: never below OVTOL
         call check_close(contact_overlap_limit(geo, diag, 0.05_wp, .false.), 0.05_wp, tol, &
                          'X-crossing: diagonal tolerance never below OVTOL')
      end associate
   end subroutine test_xcrossing_limit

   !> The corner of block `blk` at the origin (0 if none).
   integer(ip) function tip(geo, blk) result(t)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: blk
      integer(ip) :: i, q
      t = 0
      q = geo%blocks%first_corner(blk)
      do i = 1, geo%blocks%ncorner(blk)
         if (hypot(geo%corners%x(q), geo%corners%y(q)) < 1.0e-9_wp) t = q
         q = geo%corners%next(q)
      end do
   end function tip

end program test_contact_scan
