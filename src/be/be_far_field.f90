!> The boundary-element far field during a CYCLE (manual Section 3, Eq. 29,
!> F = -K u): link (BE STIFFNESS), rebuild after RESTART, the force of every
!> step and its share of the gridpoint stiffness for the time step. The
!> matrix is be_kelvin's; a deck without BE runs none of this.
!>
!> Displacements are those since the link: the node (corner) position now
!> minus its position at BE STIFFNESS, so the far field adds nothing to the
!> equilibrium the model had then (the in-situ loads of the BOUNDARY STRESS
!> stay as they are, as the manual's recommended order assumes). Nodes of
!> fully-deformable blocks move with their gridpoints and take the force
!> there; nodes of rigid blocks pass it to the block's force and moment.
!> The interface is rigid: the 1989 program joined the far field to the
!> blocks by contacts with the BE MAT material (the manual's Note under
!> BE); here the elements act on the corners directly (docs/zones.md).
module be_far_field
   use core_forces, only: add_rigid_force
   use core_kinds, only: wp, ip
   use model_properties, only: prop_bulk, prop_shear
   use core_error, only: error_t, set_error
   use core_output, only: itoa
   use model_be, only: be_t
   use model_geometry, only: geometry_t
   use model_materials, only: material_table_t
   use be_kelvin, only: be_stiffness
   use be_lapack, only: gemv
   implicit none
   private
   public :: be_link, be_ensure, be_step, be_stiffness_bound, be_node_position

contains

   !> Current position of node i.
   pure subroutine be_node_position(be, geo, i, x, y)
      type(be_t), intent(in) :: be
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: i
      real(wp), intent(out) :: x, y
      integer(ip) :: c, g
      c = be%corner(i)
      g = geo%corners%gp(c)
      if (g > 0) then
         x = geo%gridpoints%x(g)
         y = geo%gridpoints%y(g)
      else
         x = geo%corners%x(c)
         y = geo%corners%y(c)
      end if
   end subroutine be_node_position

   !> BE STIFFNESS: elastic constants of material be%mat, node positions now,
   !> the matrix. Nothing changes on error.
   subroutine be_link(be, geo, mats, error)
      type(be_t), intent(inout) :: be
      type(geometry_t), intent(in) :: geo
      type(material_table_t), intent(in) :: mats
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: bulk, shear, nu
      real(wp), allocatable :: x(:), y(:), k(:, :)
      integer(ip) :: i
      bulk = mats%get(be%mat, prop_bulk)
      shear = mats%get(be%mat, prop_shear)
      if (bulk <= 0.0_wp .or. shear <= 0.0_wp) then
         call set_error(error, 'BE STIFFNESS: material '//trim(itoa(be%mat))// &
                        ' has no bulk modulus K and shear modulus G > 0 (PROPERTY MAT='// &
                        trim(itoa(be%mat))//' K= G=)')
         return
      end if
      nu = (3.0_wp*bulk - 2.0_wp*shear)/(2.0_wp*(3.0_wp*bulk + shear))
      allocate (x(be%nc), y(be%nc))
      do i = 1, be%nc
         call be_node_position(be, geo, i, x(i), y(i))
      end do
      call build(be, x, y, shear, nu, k, error)
      if (allocated(error)) return
      call move_alloc(x, be%x0)
      call move_alloc(y, be%y0)
      call move_alloc(k, be%kmat)
      be%g = shear
      be%nu = nu
      be%linked = .true.
      call work_arrays(be)
   end subroutine be_link

   !> After RESTART the matrix is rebuilt from the saved link.
   subroutine be_ensure(be, error)
      type(be_t), intent(inout) :: be
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: k(:, :)
      if (.not. be%linked) return
      if (allocated(be%kmat)) then
         if (size(be%kmat, 1) == 2*be%nc) return
      end if
      call build(be, be%x0, be%y0, be%g, be%nu, k, error)
      if (allocated(error)) return
      call move_alloc(k, be%kmat)
      call work_arrays(be)
   end subroutine be_ensure

   subroutine build(be, x, y, shear, nu, k, error)
      type(be_t), intent(in) :: be
      real(wp), intent(in) :: x(:), y(:), shear, nu
      real(wp), allocatable, intent(out) :: k(:, :)
      type(error_t), allocatable, intent(out) :: error
      call be_stiffness(x, y, int(be%ea(1:be%ne)), int(be%eb(1:be%ne)), shear, nu, be%fix, &
                        be%xh, be%yh, be%xv, be%yv, k, error)
      if (allocated(error)) error%message = 'BE STIFFNESS: '//error%message
   end subroutine build

   subroutine work_arrays(be)
      type(be_t), intent(inout) :: be
      if (allocated(be%u)) deallocate (be%u)
      if (allocated(be%f)) deallocate (be%f)
      allocate (be%u(2*be%nc), be%f(2*be%nc))
      be%u = 0.0_wp
      be%f = 0.0_wp
   end subroutine work_arrays

   !> One step: F = -K (u - u0) into the gridpoints / blocks of the nodes.
   subroutine be_step(be, geo)
      type(be_t), intent(inout) :: be
      type(geometry_t), intent(inout) :: geo
      integer(ip) :: i, c, g, b
      real(wp) :: x, y
      do i = 1, be%nc
         call be_node_position(be, geo, i, x, y)
         be%u(2*i - 1) = x - be%x0(i)
         be%u(2*i) = y - be%y0(i)
      end do
      ! f = -K u (dense; no temporaries)
      call gemv(-1.0_wp, be%kmat, be%u, 0.0_wp, be%f)
      associate (co => geo%corners, gp => geo%gridpoints, bl => geo%blocks)
         do i = 1, be%nc
            c = be%corner(i)
            if (.not. co%live(c)) cycle
            g = co%gp(c)
            if (g > 0) then
               gp%fx(g) = gp%fx(g) + be%f(2*i - 1)
               gp%fy(g) = gp%fy(g) + be%f(2*i)
            else
               b = co%block(c)
               if (.not. bl%live(b)) cycle
               call add_rigid_force(bl%fx, bl%fy, bl%fm, b, co%x(c) - bl%xc(b), &
                                    co%y(c) - bl%yc(b), be%f(2*i - 1), be%f(2*i))
            end if
         end do
      end associate
   end subroutine be_step

   !> Add each gridpoint node's row sum of |K| (the larger of its x and y
   !> rows, a Gershgorin bound) to the gridpoint stiffness kgp of the time
   !> step (zones_mechanics).
   subroutine be_stiffness_bound(be, geo, kgp)
      type(be_t), intent(in) :: be
      type(geometry_t), intent(in) :: geo
      real(wp), intent(inout) :: kgp(:)
      integer(ip) :: i, g
      do i = 1, be%nc
         g = geo%corners%gp(be%corner(i))
         if (g <= 0 .or. g > size(kgp)) cycle
         kgp(g) = kgp(g) + max(sum(abs(be%kmat(2*i - 1, :))), sum(abs(be%kmat(2*i, :))))
      end do
   end subroutine be_stiffness_bound


end module be_far_field
