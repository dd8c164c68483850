!> Beam-element models of structural elements (manual Section 3.11, Fig. 3-20):
!> an abstract base type and a factory, called once per material group with
!> the loop over that group's elements inside the kernel.
!>
!> ELASTIC: the local stiffness matrix of Fig. 3-20 in a co-rotational frame
!> (the frame turns with the chord, so large rigid rotations give no force):
!>   axial force  N  = E A / L0 (L - L0)             (tension positive)
!>   end moments  M1 = E I / L0 (4 t1 + 2 t2),  M2 = E I / L0 (2 t1 + 4 t2)
!>   shear force  V  = (M1 + M2) / L
!> with t1, t2 the node rotations less the chord rotation beta. The forces on
!> the nodes are those of the virtual work N dL + M1 dt1 + M2 dt2 (e the unit
!> chord vector, n = (-e_y, e_x)): node 1 gets N e - V n and moment -M1,
!> node 2 gets -N e + V n and moment -M2. For small displacements this is the
!> cubic (Hermite) beam: end-loaded cantilever and mid-loaded simple beam
!> are exact at the nodes.
module structure_models
   use core_constants, only: pi
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use model_structures, only: structure_t
   implicit none
   private
   public :: beam_props_t, beam_model_t, beam_elastic_t, beam_model_create, beam_model_names


   !> Material data of one group.
   type :: beam_props_t
      integer(ip) :: material = 0
      real(wp) :: young = 0.0_wp, density = 0.0_wp
   end type beam_props_t

   !> Element law of one material group.
   type, abstract :: beam_model_t
   contains
      procedure(beam_forces_i), deferred :: forces
   end type beam_model_t

   abstract interface
      !> Element forces of the elements `idx` added to the node sums.
      subroutine beam_forces_i(this, st, idx, props)
         import :: beam_model_t, structure_t, ip, beam_props_t
         class(beam_model_t), intent(in) :: this
         type(structure_t), intent(inout) :: st
         integer(ip), intent(in) :: idx(:)
         type(beam_props_t), intent(in) :: props
      end subroutine beam_forces_i
   end interface

   type, extends(beam_model_t) :: beam_elastic_t
   contains
      procedure :: forces => beam_elastic_forces
   end type beam_elastic_t

   !> Known element models, in factory order.
   character(len=*), parameter :: beam_model_names(1) = ['ELASTIC']

contains

   !> The element model called `name` (one of beam_model_names).
   subroutine beam_model_create(name, model, error)
      character(len=*), intent(in) :: name
      class(beam_model_t), allocatable, intent(out) :: model
      type(error_t), allocatable, intent(out) :: error
      select case (name)
      case ('ELASTIC')
         allocate (beam_elastic_t :: model)
      case default
         call set_error(error, 'structural element model "'//name//'" is unknown; known: ELASTIC')
      end select
   end subroutine beam_model_create

   subroutine beam_elastic_forces(this, st, idx, props)
      class(beam_elastic_t), intent(in) :: this
      type(structure_t), intent(inout) :: st
      integer(ip), intent(in) :: idx(:)
      type(beam_props_t), intent(in) :: props
      integer(ip) :: j, e, a, b
      real(wp) :: dx, dy, l, ex, ey, beta, t1, t2, k, m1, m2, n, v, fx, fy
      associate (nd => st%nodes, el => st%elements)
         do j = 1, size(idx)
            e = idx(j)
            a = el%n1(e)
            b = el%n2(e)
            dx = nd%x(b) - nd%x(a)
            dy = nd%y(b) - nd%y(a)
            l = hypot(dx, dy)
            ex = dx/l
            ey = dy/l
            beta = atan2(dy, dx) - el%angle0(e)
            beta = modulo(beta + pi, 2.0_wp*pi) - pi
            t1 = nd%rot(a) - beta
            t2 = nd%rot(b) - beta
            k = props%young*el%inertia(e)/el%length0(e)
            m1 = k*(4.0_wp*t1 + 2.0_wp*t2)
            m2 = k*(2.0_wp*t1 + 4.0_wp*t2)
            n = props%young*el%area(e)/el%length0(e)*(l - el%length0(e))
            v = (m1 + m2)/l
            fx = n*ex + v*ey         ! N e - V n, n = (-ey, ex)
            fy = n*ey - v*ex
            nd%fx(a) = nd%fx(a) + fx
            nd%fy(a) = nd%fy(a) + fy
            nd%fm(a) = nd%fm(a) - m1
            nd%fx(b) = nd%fx(b) - fx
            nd%fy(b) = nd%fy(b) - fy
            nd%fm(b) = nd%fm(b) - m2
            el%axial(e) = n
            el%shear(e) = v
            el%m1(e) = m1
            el%m2(e) = m2
         end do
      end associate
   end subroutine beam_elastic_forces

end module structure_models
