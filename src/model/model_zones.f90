!> Fully-deformable blocks (manual Section 3.2, 4.5 GENERATE): gridpoints and
!> constant-strain triangular zones.
!>
!> A fully-deformable (FDEF) block is cut into triangles whose vertices are
!> gridpoints. Every corner of an FDEF block is a gridpoint (`corner`: its
!> corner id, `corners%gp` points back); gridpoints inside the block have
!> corner 0. Zones and gridpoints of one block are stored contiguously
!> (`blocks%zfirst/nzone`, `blocks%gfirst/ngp`), zone vertices counter-
!> clockwise (positive area). Ids are array indices and are not reused.
!>
!> Stress sign convention (manual 4.1): tension positive, so in-situ
!> compression is negative. Velocities are at t - dt/2 between steps; `fx`,
!> `fy` hold the force sums of the last step (zones, contacts, boundary),
!> which is the reaction at a gridpoint whose velocity is prescribed.
module model_zones
   use core_kinds, only: wp, ip, l1
   use core_arrays, only: grow_array, grow_lists
   implicit none
   private
   public :: gridpoint_list_t, zone_list_t, zones_add_gridpoint, zones_add_zone
   public :: zone_elastic, zone_at_failure, zone_failed_past, zone_tension
   public :: vfix_x, vfix_y

   !> Plasticity indicator of a zone (PRINT ZONE STRESS, manual 4.5).
   integer, parameter :: zone_elastic = 0, zone_at_failure = 1, zone_failed_past = 2, &
                         zone_tension = 3

   !> Bits of `gridpoints%vfix`: velocity prescribed in x / y (BOUNDARY XVEL/YVEL).
   integer, parameter :: vfix_x = 1, vfix_y = 2

   type :: gridpoint_list_t
      integer(ip) :: n = 0
      logical(l1), allocatable :: live(:)
      integer(ip), allocatable :: block(:)      !< owning block
      integer(ip), allocatable :: corner(:)     !< corner id if on the block boundary, else 0
      real(wp), allocatable :: x(:), y(:)       !< current position
      real(wp), allocatable :: vx(:), vy(:)     !< velocity
      real(wp), allocatable :: ux(:), uy(:)     !< accumulated displacement
      real(wp), allocatable :: fx(:), fy(:)     !< force sum of the last step
      real(wp), allocatable :: mass(:)          !< lumped (unscaled) mass
      integer, allocatable :: vfix(:)           !< vfix_x / vfix_y bits
      integer(ip), allocatable :: addr(:)       !< 1989 IA address (model_address)
   end type gridpoint_list_t

   type :: zone_list_t
      integer(ip) :: n = 0
      logical(l1), allocatable :: live(:)
      integer(ip), allocatable :: block(:)
      integer(ip), allocatable :: g1(:), g2(:), g3(:)   !< vertices, counter-clockwise
      real(wp), allocatable :: sxx(:), sxy(:), syy(:), szz(:)   !< stresses (tension +)
      integer, allocatable :: state(:)                  !< plasticity indicator
      integer(ip), allocatable :: addr(:)               !< 1989 IA address (model_address)
   end type zone_list_t

contains

   !> Append a gridpoint of block `block` at (x, y); `corner` 0 if interior.
   subroutine zones_add_gridpoint(gp, block, corner, x, y, id)
      type(gridpoint_list_t), intent(inout) :: gp
      integer(ip), intent(in) :: block, corner
      real(wp), intent(in) :: x, y
      integer(ip), intent(out) :: id
      integer(ip) :: m
      m = capacity_for_one_more(gp%live, gp%n)
      if (m > 0) call grow_gridpoints(gp, m)
      gp%n = gp%n + 1; id = gp%n
      gp%live(id) = .true.; gp%block(id) = block; gp%corner(id) = corner
      gp%x(id) = x; gp%y(id) = y
      ! at rest, unloaded, massless, free, without an address
      gp%vx(id) = 0.0_wp; gp%vy(id) = 0.0_wp; gp%ux(id) = 0.0_wp; gp%uy(id) = 0.0_wp
      gp%fx(id) = 0.0_wp; gp%fy(id) = 0.0_wp; gp%mass(id) = 0.0_wp
      gp%vfix(id) = 0; gp%addr(id) = 0
   end subroutine zones_add_gridpoint

   !> Append a zone of block `block` with vertices g1 g2 g3 (counter-clockwise).
   subroutine zones_add_zone(zn, block, g1, g2, g3, id)
      type(zone_list_t), intent(inout) :: zn
      integer(ip), intent(in) :: block, g1, g2, g3
      integer(ip), intent(out) :: id
      integer(ip) :: m
      m = capacity_for_one_more(zn%live, zn%n)
      if (m > 0) call grow_zones(zn, m)
      zn%n = zn%n + 1; id = zn%n
      zn%live(id) = .true.; zn%block(id) = block
      zn%g1(id) = g1; zn%g2(id) = g2; zn%g3(id) = g3
      ! unstressed, elastic, without an address
      zn%sxx(id) = 0.0_wp; zn%sxy(id) = 0.0_wp; zn%syy(id) = 0.0_wp; zn%szz(id) = 0.0_wp
      zn%state(id) = zone_elastic; zn%addr(id) = 0
   end subroutine zones_add_zone

   !> Capacity to grow a list of n entries (`live` its flags) to before one more
   !> is appended: 256 when it has none, twice its size when it is full, 0 when
   !> it has room.
   pure integer(ip) function capacity_for_one_more(live, n) result(m)
      logical(l1), allocatable, intent(in) :: live(:)
      integer(ip), intent(in) :: n
      m = 0
      if (.not. allocated(live)) then
         m = 256
      else if (n >= size(live)) then
         m = 2_ip*size(live)
      end if
   end function capacity_for_one_more

   subroutine grow_gridpoints(g, m)
      type(gridpoint_list_t), intent(inout) :: g
      integer(ip), intent(in) :: m
      call grow_lists(g%n, m, g%x, g%y, g%vx, g%vy, g%ux, g%uy, g%fx, g%fy, g%mass)
      call grow_lists(g%n, m, g%block, g%corner, g%vfix, g%addr)
      call grow_array(g%live, g%n, m)
   end subroutine grow_gridpoints

   subroutine grow_zones(z, m)
      type(zone_list_t), intent(inout) :: z
      integer(ip), intent(in) :: m
      call grow_lists(z%n, m, z%sxx, z%sxy, z%syy, z%szz)
      call grow_lists(z%n, m, z%block, z%g1, z%g2, z%g3, z%state, z%addr)
      call grow_array(z%live, z%n, m)
   end subroutine grow_zones

end module model_zones
