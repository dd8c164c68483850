!> Contact normal between two coincident gridpoints in the middle of zoned
!> edges (straight corners, radius 0) when the joint closes.
!>
!> Two zoned blocks stacked (0..1 x 0..1 and 0..1 x 1..2, GEN QUAD 0.5):
!> the joint y = 1 has a contact between the mid-edge gridpoints at
!> (0.5, 1). Its corner circles are points, so once the upper gridpoint
!> moves below the lower one (the joint closes, the normal "overlap" every
!> loaded joint has) the line of centres turns round. Before the fix in
!> contact_kinematics (cone_side) that reversed line was taken as the
!> normal: the closing joint printed as opening in tension and, with
!> JTENS = 0, broke. Reference: the normal must point from block1 into
!> block2 (manual Fig 3-3: the joint normal of the lower block's face), i.e.
!> n . (centroid2 - centroid1) > 0, and the gap must be the negative overlap
!> (-1e-4, to 1e-12), each time the joint is closed again.
program test_contact_flat_corner
   use core_kinds, only: wp, ip
   use core_error, only: error_t
   use commands_session, only: session_t, session_init
   use contact_kinematics, only: contact_geometry
   use testing, only: check, check_close, testing_finish
   use testing_session, only: session_run
   implicit none
   type(session_t) :: s
   character(len=200), allocatable :: lines(:)
   integer(ip) :: c, mid, b1, b2
   real(wp) :: gap, nx, ny, px, py, dir
   integer :: k
   type(error_t), allocatable :: error

   call session_init(s, error)
   call check(.not. allocated(error), 'session starts')
   call session_run(s, 'ROUND 0.01', lines)
   call session_run(s, 'BLOCK 0,0 0,2 1,2 1,0', lines)
   call session_run(s, 'CRACK 0,1 1,1', lines)
   call session_run(s, 'GEN QUAD 0.5', lines)
   call session_run(s, 'PROP MAT=1 D=2000 K=1E9 G=6E8 JKN=1E10 JKS=1E10', lines)
   call session_run(s, 'CYCLE 1', lines)
   associate (geo => s%model%geometry)
      ! the contact at (0.5, 1)
      mid = 0
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         if (abs(geo%contacts%x(c) - 0.5_wp) < 1.0e-3_wp) mid = c
      end do
      call check(mid > 0, 'contact between the mid-edge gridpoints found')
      if (mid == 0) call testing_finish()
      b1 = geo%contacts%block1(mid)
      b2 = geo%contacts%block2(mid)
      do k = 1, 3
         ! close the joint by 1e-4: the upper block moves down as a whole, so
         ! both gridpoints at (0.5, 1) stay straight corners
         call shift_upper(geo, -1.0e-4_wp)
         call contact_geometry(geo, mid, 1.0e-5_wp, gap, nx, ny, px, py)
         dir = nx*(geo%blocks%xc(b2) - geo%blocks%xc(b1)) + ny*(geo%blocks%yc(b2) - geo%blocks%yc(b1))
         call check(dir > 0.0_wp, 'normal points from block1 into block2 after the joint closed')
         call check_close(gap, -1.0e-4_wp, 1.0e-12_wp, 'gap = - overlap (1e-12)')
         call shift_upper(geo, 1.0e-4_wp)
      end do
   end associate
   call testing_finish()

contains

   !> Move the gridpoints and corners of the upper block (centroid above y = 1) by dy.
   subroutine shift_upper(geo, dy)
      use model_geometry, only: geometry_t
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: dy
      integer(ip) :: q
      do q = 1, geo%corners%n
         if (.not. geo%corners%live(q)) cycle
         if (geo%blocks%yc(geo%corners%block(q)) < 1.0_wp) cycle
         geo%corners%y(q) = geo%corners%y(q) + dy
         geo%corners%ry(q) = geo%corners%ry(q) + dy
      end do
      do q = 1, geo%gridpoints%n
         if (.not. geo%gridpoints%live(q)) cycle
         if (geo%blocks%yc(geo%gridpoints%block(q)) < 1.0_wp) cycle
         geo%gridpoints%y(q) = geo%gridpoints%y(q) + dy
      end do
   end subroutine shift_upper
end program test_contact_flat_corner
