!> The zone mesh of one block (mesh_t) as GENERATE produces it, the
!> triangle-index helpers every mesher shares, and mesh queries.
module zones_mesh_base
   use core_kinds, only: wp, ip
   use core_constants, only: pi
   implicit none
   private
   public :: mesh_t, mesh_target_angle, nxt, prv, orient, mesh_min_angle, mesh_area
   public :: mesh_sharpest_zone, mesh_smallest_zone

   !> Smallest zone angle Delaunay refinement aims at (degrees).
   real(wp), parameter :: mesh_target_angle = 25.0_wp

   type :: mesh_t
      integer(ip) :: nb = 0                     !< boundary ring points (first nb)
      integer(ip) :: np = 0                     !< all points
      real(wp), allocatable :: x(:), y(:)
      integer(ip), allocatable :: orig(:)       !< ring point: index of the input corner, or 0
      integer(ip) :: nt = 0
      integer(ip), allocatable :: tri(:, :)     !< (3, nt), counter-clockwise
   end type mesh_t

contains

   pure integer(ip) function nxt(i)
      integer(ip), intent(in) :: i
      nxt = merge(1_ip, i + 1, i == 3)
   end function nxt

   pure integer(ip) function prv(i)
      integer(ip), intent(in) :: i
      prv = merge(3_ip, i - 1, i == 1)
   end function prv

   pure real(wp) function orient(ax, ay, bx, by, cx, cy)
      real(wp), intent(in) :: ax, ay, bx, by, cx, cy
      orient = (bx - ax)*(cy - ay) - (by - ay)*(cx - ax)
   end function orient

   !> Smallest zone angle of a mesh (degrees).
   pure real(wp) function mesh_min_angle(mesh) result(amin)
      type(mesh_t), intent(in) :: mesh
      real(wp) :: xa, ya, area
      call mesh_sharpest_zone(mesh, amin, xa, ya, area)
   end function mesh_min_angle

   !> The smallest zone angle (degrees), the corner (xa, ya) where it is, and
   !> the area of that zone.
   pure subroutine mesh_sharpest_zone(mesh, amin, xa, ya, area)
      type(mesh_t), intent(in) :: mesh
      real(wp), intent(out) :: amin, xa, ya, area
      integer(ip) :: t, i, a, b, c
      real(wp) :: ux, uy, vx, vy, ang
      amin = 180.0_wp
      xa = 0.0_wp
      ya = 0.0_wp
      area = 0.0_wp
      do t = 1, mesh%nt
         do i = 1, 3
            a = mesh%tri(i, t)
            b = mesh%tri(merge(1, i + 1, i == 3), t)
            c = mesh%tri(merge(3, i - 1, i == 1), t)
            ux = mesh%x(b) - mesh%x(a); uy = mesh%y(b) - mesh%y(a)
            vx = mesh%x(c) - mesh%x(a); vy = mesh%y(c) - mesh%y(a)
            ang = abs(atan2(ux*vy - uy*vx, ux*vx + uy*vy))*180.0_wp/pi
            if (ang < amin) then
               amin = ang
               xa = mesh%x(a)
               ya = mesh%y(a)
               area = 0.5_wp*abs(ux*vy - uy*vx)
            end if
         end do
      end do
   end subroutine mesh_sharpest_zone

   !> The zone of least area: its area and centroid (area huge, centroid 0
   !> for a mesh without zones).
   pure subroutine mesh_smallest_zone(mesh, area, xc, yc)
      type(mesh_t), intent(in) :: mesh
      real(wp), intent(out) :: area, xc, yc
      integer(ip) :: t
      real(wp) :: a
      area = huge(1.0_wp)
      xc = 0.0_wp
      yc = 0.0_wp
      do t = 1, mesh%nt
         associate (v => mesh%tri(:, t))
            a = 0.5_wp*abs(orient(mesh%x(v(1)), mesh%y(v(1)), mesh%x(v(2)), mesh%y(v(2)), &
                                  mesh%x(v(3)), mesh%y(v(3))))
            if (a < area) then
               area = a
               xc = sum(mesh%x(v))/3.0_wp
               yc = sum(mesh%y(v))/3.0_wp
            end if
         end associate
      end do
   end subroutine mesh_smallest_zone

   !> Sum of the signed zone areas (counter-clockwise positive).
   pure real(wp) function mesh_area(mesh) result(a)
      type(mesh_t), intent(in) :: mesh
      integer(ip) :: t
      a = 0.0_wp
      do t = 1, mesh%nt
         associate (v => mesh%tri(:, t))
            a = a + 0.5_wp*orient(mesh%x(v(1)), mesh%y(v(1)), mesh%x(v(2)), mesh%y(v(2)), &
                                  mesh%x(v(3)), mesh%y(v(3)))
         end associate
      end do
   end function mesh_area

end module zones_mesh_base
