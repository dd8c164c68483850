!> Structural elements (manual Sections 3.11, 4.5 STRUCTURE, 6.1 "Offsets for
!> Structural Element ..."): beam elements of a tunnel lining joined at lumped
!> masses (nodes), and the interfaces that tie the nodes to the rock blocks.
!>
!> Nodes are the manual's lumped-mass array (ILMPNT): position, velocity,
!> angular velocity, accumulated displacement and rotation, force and moment
!> sums of the last step, masses, applied load. Elements (ISTEPNT) join two
!> nodes; their section (area = thickness x 1, I = thickness^3 / 12) and
!> Young's modulus E = 9KG / (3K + G) come from the element material at the
!> start of every CYCLE; the forces are those of the last step:
!> axial force (tension positive, so thrust = -axial), shear force and the
!> end moments (counter-clockwise positive, acting on the element).
!> Interfaces (INTPNT) tie one node to the edge of one block: the edge starts
!> at corner `edge` of the block's clockwise ring; normal (nx, ny) points out
!> of the block towards the node; un / us accumulated relative displacement of
!> the node with respect to the block (un > 0 opening), fn (compression
!> positive) and fs along (-ny, nx).
!>
!> The whole type is an allocatable component of model_t: a model without
!> STRUCTURE has none and runs no structure code.
module model_structures
   use core_kinds, only: wp, ip
   use core_arrays, only: grow_lists
   implicit none
   private
   public :: structure_t, structure_node_list_t, structure_element_list_t, &
      structure_interface_list_t, structure_add_node, structure_add_element, &
      structure_add_interface, sfix_x, sfix_y, sfix_r, iface_broken, iface_slip

   !> Bits of `nodes%fix`: velocity held in x, y, rotation.
   integer, parameter :: sfix_x = 1, sfix_y = 2, sfix_r = 4
   !> Bits of `interfaces%flags`: tensile strength exceeded (no tension and no
   !> cohesion afterwards), sliding at the last step.
   integer, parameter :: iface_broken = 1, iface_slip = 2

   type :: structure_node_list_t
      integer(ip) :: n = 0
      real(wp), allocatable :: x(:), y(:)               !< current position
      real(wp), allocatable :: vx(:), vy(:), vr(:)      !< velocity, angular velocity (ccw)
      real(wp), allocatable :: ux(:), uy(:), rot(:)     !< accumulated displacement, rotation
      real(wp), allocatable :: fx(:), fy(:), fm(:)      !< force and moment sums of the last step
      real(wp), allocatable :: mass(:), inertia(:)      !< lumped (unscaled) mass, rotary inertia
      real(wp), allocatable :: lx(:), ly(:)             !< applied load (manual KXL, KYL)
      integer, allocatable :: fix(:)                    !< sfix_* bits
      integer(ip), allocatable :: material(:)
   end type structure_node_list_t

   type :: structure_element_list_t
      integer(ip) :: n = 0
      integer(ip), allocatable :: n1(:), n2(:), material(:)
      real(wp), allocatable :: thick(:)                 !< lining thickness
      real(wp), allocatable :: length0(:), angle0(:)    !< length and chord angle when built
      real(wp), allocatable :: young(:), area(:), inertia(:)   !< E, A, I (from the material)
      real(wp), allocatable :: axial(:), shear(:)       !< forces of the last step
      real(wp), allocatable :: m1(:), m2(:)             !< end moments of the last step
   end type structure_element_list_t

   type :: structure_interface_list_t
      integer(ip) :: n = 0
      integer(ip), allocatable :: node(:), block(:), edge(:), material(:)
      real(wp), allocatable :: x(:), y(:)               !< contact point on the edge
      real(wp), allocatable :: nx(:), ny(:)             !< edge normal (out of the block)
      real(wp), allocatable :: un(:), us(:), fn(:), fs(:)
      integer, allocatable :: flags(:)
   end type structure_interface_list_t

   type :: structure_t
      type(structure_node_list_t) :: nodes
      type(structure_element_list_t) :: elements
      type(structure_interface_list_t) :: interfaces
   end type structure_t

contains

   !> Capacity to grow a list of n entries to before one more is appended
   !> (16, then doubling), `a` one of its arrays; 0 when it has room.
   pure integer(ip) function grown_capacity(n, a) result(cap)
      integer(ip), intent(in) :: n
      real(wp), allocatable, intent(in) :: a(:)
      cap = 0
      if (allocated(a)) cap = size(a, kind=ip)
      cap = merge(max(16_ip, 2_ip*cap), 0_ip, n >= cap)
   end function grown_capacity

   !> Append a node at (x, y) of material `mat`; `id` its index.
   subroutine structure_add_node(st, x, y, mat, id)
      type(structure_t), intent(inout) :: st
      real(wp), intent(in) :: x, y
      integer(ip), intent(in) :: mat
      integer(ip), intent(out) :: id
      integer(ip) :: cap
      associate (nd => st%nodes)
         cap = grown_capacity(nd%n, nd%x)
         if (cap > 0) then
            call grow_lists(nd%n, cap, nd%x, nd%y, nd%vx, nd%vy, nd%vr, nd%ux, nd%uy, nd%rot, &
                            nd%fx, nd%fy, nd%fm, nd%mass, nd%inertia, nd%lx, nd%ly)
            call grow_lists(nd%n, cap, nd%fix, nd%material)
         end if
         nd%n = nd%n + 1; id = nd%n
         nd%x(id) = x; nd%y(id) = y
         nd%vx(id) = 0.0_wp; nd%vy(id) = 0.0_wp; nd%vr(id) = 0.0_wp
         nd%ux(id) = 0.0_wp; nd%uy(id) = 0.0_wp; nd%rot(id) = 0.0_wp
         nd%fx(id) = 0.0_wp; nd%fy(id) = 0.0_wp; nd%fm(id) = 0.0_wp
         nd%mass(id) = 0.0_wp; nd%inertia(id) = 0.0_wp
         nd%lx(id) = 0.0_wp; nd%ly(id) = 0.0_wp
         nd%fix(id) = 0
         nd%material(id) = mat
      end associate
   end subroutine structure_add_node

   !> Append a beam element from node n1 to node n2 (stress-free as they are now).
   subroutine structure_add_element(st, n1, n2, mat, thick, id)
      type(structure_t), intent(inout) :: st
      integer(ip), intent(in) :: n1, n2, mat
      real(wp), intent(in) :: thick
      integer(ip), intent(out) :: id
      integer(ip) :: cap
      associate (el => st%elements, nd => st%nodes)
         cap = grown_capacity(el%n, el%thick)
         if (cap > 0) then
            call grow_lists(el%n, cap, el%thick, el%length0, el%angle0, el%young, el%area, &
                            el%inertia, el%axial, el%shear, el%m1, el%m2)
            call grow_lists(el%n, cap, el%n1, el%n2, el%material)
         end if
         el%n = el%n + 1
         id = el%n
         el%n1(id) = n1; el%n2(id) = n2
         el%material(id) = mat
         el%thick(id) = thick
         el%length0(id) = hypot(nd%x(n2) - nd%x(n1), nd%y(n2) - nd%y(n1))
         el%angle0(id) = atan2(nd%y(n2) - nd%y(n1), nd%x(n2) - nd%x(n1))
         el%young(id) = 0.0_wp
         el%area(id) = thick
         el%inertia(id) = thick**3/12.0_wp
         el%axial(id) = 0.0_wp; el%shear(id) = 0.0_wp
         el%m1(id) = 0.0_wp; el%m2(id) = 0.0_wp
      end associate
   end subroutine structure_add_element

   !> Append an interface between node `node` and the edge of block `block`
   !> starting at corner `edge`, touching at (x, y) with outward normal (nx, ny).
   subroutine structure_add_interface(st, node, block, edge, mat, x, y, nx, ny, id)
      type(structure_t), intent(inout) :: st
      integer(ip), intent(in) :: node, block, edge, mat
      real(wp), intent(in) :: x, y, nx, ny
      integer(ip), intent(out) :: id
      integer(ip) :: cap
      associate (it => st%interfaces)
         cap = grown_capacity(it%n, it%x)
         if (cap > 0) then
            call grow_lists(it%n, cap, it%x, it%y, it%nx, it%ny, it%un, it%us, it%fn, it%fs)
            call grow_lists(it%n, cap, it%node, it%block, it%edge, it%material, it%flags)
         end if
         it%n = it%n + 1
         id = it%n
         it%node(id) = node; it%block(id) = block; it%edge(id) = edge
         it%material(id) = mat
         it%x(id) = x; it%y(id) = y; it%nx(id) = nx; it%ny(id) = ny
         it%un(id) = 0.0_wp; it%us(id) = 0.0_wp
         it%fn(id) = 0.0_wp; it%fs(id) = 0.0_wp
         it%flags(id) = 0
      end associate
   end subroutine structure_add_interface

end module model_structures
