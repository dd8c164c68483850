!> Rock reinforcement (UDEC manual (ICG1.5, 1989), Section 3.10; commands
!> REINFORCE and CABLE of Section 4.5; the manual's "Offsets for Local
!> Reinforcement Array" and "Offsets for Cable Reinforcing" of Section 6.1).
!>
!> Local reinforcement (REINFORCE, Section 3.10.1): one element where a line
!> crosses a joint, between block 1 (the side the line comes from) and block
!> 2. Each side is a material point: on a rigid block it moves with the block
!> (x1, y1 / x2, y2 follow the block velocity), on a zoned (FDEF) block it is
!> a fraction w of the boundary edge between two gridpoints (g1a-g1b /
!> g2a-g2b). The bolt axis (ax, ay) points from block 1 to block 2, the joint
!> tangent (tx, ty) is that of block 1's edge at the crossing. (dx, dy): the
!> displacement of side 2 relative to side 1 since the element was made;
!> uaxial: the sum of its increments along the active length; fa (tension
!> positive) and fs the forces of the axial and shear springs; fjs, fjn
!> their resultant along the joint tangent and normal (the manual's KCFS,
!> KCFN; fjn > 0 pulls the blocks together).
!>
!> Cables (CABLE, Section 3.10.2): nodes (lumped masses) joined by axial
!> elements. A node lies in a zone of an FDEF block (weights w1..w3 of the
!> zone's gridpoints, Eq. 49), on a rigid block (host block, the material
!> point hx, hy moving with it) or in no block (free node, two degrees of
!> freedom). A hosted node moves with its host across the cable and slips
!> along it (vs, the slip velocity); the grout spring (force fg along the
!> axis, per node: JKS and JCOH times the node's length of cable glen)
!> resists the slip. Elements: axial force (tension positive) of the last
!> step, the length of the last step, the pretension it started with.
!>
!> The whole type is an allocatable component of model_t: a model without
!> REINFORCE or CABLE has none and runs no reinforcement code.
module model_reinforcement
   use core_kinds, only: wp, ip
   implicit none
   private
   public :: reinforcement_t, reinf_list_t, cable_node_list_t, cable_element_list_t, &
      reinf_add, cable_add_node, cable_add_element, reinforcement_present, reinf_joint_normal

   type :: reinf_list_t
      integer(ip) :: n = 0
      integer(ip), allocatable :: material(:), block1(:), block2(:)
      integer(ip), allocatable :: g1a(:), g1b(:), g2a(:), g2b(:)   !< FDEF edge gridpoints (0: rigid)
      real(wp), allocatable :: w1(:), w2(:)                        !< fraction along those edges
      real(wp), allocatable :: x1(:), y1(:), x2(:), y2(:)          !< material points of the sides
      real(wp), allocatable :: ax(:), ay(:), tx(:), ty(:)          !< bolt axis, joint tangent
      real(wp), allocatable :: dx(:), dy(:), uaxial(:)
      real(wp), allocatable :: fa(:), fs(:), fjs(:), fjn(:)
   end type reinf_list_t

   type :: cable_node_list_t
      integer(ip) :: n = 0
      integer(ip), allocatable :: cable(:), block(:), zone(:)      !< host block / zone (0: none)
      integer(ip), allocatable :: matg(:)                          !< grout material
      real(wp), allocatable :: w1(:), w2(:), w3(:)                 !< zone weights (Eq. 49)
      real(wp), allocatable :: x(:), y(:), hx(:), hy(:)            !< node, host material point
      real(wp), allocatable :: vs(:), vx(:), vy(:)                 !< slip velocity; free node velocity
      real(wp), allocatable :: fx(:), fy(:)                        !< element force sums of the last step
      real(wp), allocatable :: fg(:), slip(:), glen(:), mass(:)
   end type cable_node_list_t

   type :: cable_element_list_t
      integer(ip) :: n = 0
      integer(ip), allocatable :: cable(:), n1(:), n2(:), mats(:)
      real(wp), allocatable :: area(:), length0(:), length(:), axial(:), pre(:)
   end type cable_element_list_t

   type :: reinforcement_t
      type(reinf_list_t) :: reinf
      type(cable_node_list_t) :: nodes
      type(cable_element_list_t) :: elements
      integer(ip) :: ncable = 0
   end type reinforcement_t

contains

   !> True when the model has reinforcement elements or cables.
   pure logical function reinforcement_present(rf) result(yes)
      type(reinforcement_t), allocatable, intent(in) :: rf
      yes = .false.
      if (allocated(rf)) yes = rf%reinf%n > 0 .or. rf%nodes%n > 0
   end function reinforcement_present

   !> Append a local reinforcement element (fields as in the module header).
   subroutine reinf_add(r, mat, b1, b2, g1a, g1b, w1, g2a, g2b, w2, x1, y1, x2, y2, ax, ay, tx, ty)
      type(reinf_list_t), intent(inout) :: r
      integer(ip), intent(in) :: mat, b1, b2, g1a, g1b, g2a, g2b
      real(wp), intent(in) :: w1, w2, x1, y1, x2, y2, ax, ay, tx, ty
      if (.not. allocated(r%material)) then
         allocate (r%material(0), r%block1(0), r%block2(0), r%g1a(0), r%g1b(0), r%g2a(0), &
                   r%g2b(0), r%w1(0), r%w2(0), r%x1(0), r%y1(0), r%x2(0), r%y2(0), r%ax(0), &
                   r%ay(0), r%tx(0), r%ty(0), r%dx(0), r%dy(0), r%uaxial(0), r%fa(0), r%fs(0), &
                   r%fjs(0), r%fjn(0))
      end if
      r%n = r%n + 1
      r%material = [r%material, mat]; r%block1 = [r%block1, b1]; r%block2 = [r%block2, b2]
      r%g1a = [r%g1a, g1a]; r%g1b = [r%g1b, g1b]; r%g2a = [r%g2a, g2a]; r%g2b = [r%g2b, g2b]
      r%w1 = [r%w1, w1]; r%w2 = [r%w2, w2]
      r%x1 = [r%x1, x1]; r%y1 = [r%y1, y1]; r%x2 = [r%x2, x2]; r%y2 = [r%y2, y2]
      r%ax = [r%ax, ax]; r%ay = [r%ay, ay]; r%tx = [r%tx, tx]; r%ty = [r%ty, ty]
      r%dx = [r%dx, 0.0_wp]; r%dy = [r%dy, 0.0_wp]; r%uaxial = [r%uaxial, 0.0_wp]
      r%fa = [r%fa, 0.0_wp]; r%fs = [r%fs, 0.0_wp]; r%fjs = [r%fjs, 0.0_wp]
      r%fjn = [r%fjn, 0.0_wp]
   end subroutine reinf_add

   !> Append a cable node at (x, y) with its host (block, zone 0 for a rigid
   !> block; block 0 for a free node) and zone weights.
   subroutine cable_add_node(d, cable, b, z, w, x, y, matg, glen)
      type(cable_node_list_t), intent(inout) :: d
      integer(ip), intent(in) :: cable, b, z, matg
      real(wp), intent(in) :: w(3), x, y, glen
      if (.not. allocated(d%cable)) then
         allocate (d%cable(0), d%block(0), d%zone(0), d%matg(0), d%w1(0), d%w2(0), d%w3(0), &
                   d%x(0), d%y(0), d%hx(0), d%hy(0), d%vs(0), d%vx(0), d%vy(0), d%fx(0), &
                   d%fy(0), d%fg(0), d%slip(0), d%glen(0), d%mass(0))
      end if
      d%n = d%n + 1
      d%cable = [d%cable, cable]; d%block = [d%block, b]; d%zone = [d%zone, z]
      d%matg = [d%matg, matg]
      d%w1 = [d%w1, w(1)]; d%w2 = [d%w2, w(2)]; d%w3 = [d%w3, w(3)]
      d%x = [d%x, x]; d%y = [d%y, y]; d%hx = [d%hx, x]; d%hy = [d%hy, y]
      d%vs = [d%vs, 0.0_wp]; d%vx = [d%vx, 0.0_wp]; d%vy = [d%vy, 0.0_wp]
      d%fx = [d%fx, 0.0_wp]; d%fy = [d%fy, 0.0_wp]; d%fg = [d%fg, 0.0_wp]
      d%slip = [d%slip, 0.0_wp]; d%glen = [d%glen, glen]; d%mass = [d%mass, 0.0_wp]
   end subroutine cable_add_node

   !> Append a cable element between nodes a and b (stress-free but for its
   !> pretension `pre`).
   subroutine cable_add_element(e, cable, a, b, mats, area, l0, pre)
      type(cable_element_list_t), intent(inout) :: e
      integer(ip), intent(in) :: cable, a, b, mats
      real(wp), intent(in) :: area, l0, pre
      if (.not. allocated(e%cable)) then
         allocate (e%cable(0), e%n1(0), e%n2(0), e%mats(0), e%area(0), e%length0(0), &
                   e%length(0), e%axial(0), e%pre(0))
      end if
      e%n = e%n + 1
      e%cable = [e%cable, cable]; e%n1 = [e%n1, a]; e%n2 = [e%n2, b]; e%mats = [e%mats, mats]
      e%area = [e%area, area]; e%length0 = [e%length0, l0]; e%length = [e%length, l0]
      e%axial = [e%axial, pre]; e%pre = [e%pre, pre]
   end subroutine cable_add_element

   !> Unit normal of the joint that reinforcement i crosses, from side 1
   !> towards side 2 (the side the bolt axis points into).
   pure subroutine reinf_joint_normal(r, i, nx, ny)
      type(reinf_list_t), intent(in) :: r
      integer(ip), intent(in) :: i
      real(wp), intent(out) :: nx, ny
      nx = -r%ty(i)
      ny = r%tx(i)
      if (nx*r%ax(i) + ny*r%ay(i) < 0.0_wp) then
         nx = -nx
         ny = -ny
      end if
   end subroutine reinf_joint_normal

end module model_reinforcement
