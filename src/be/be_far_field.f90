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
   use core_output, only: itoa, format_real
   use model_be, only: be_t
   use model_geometry, only: geometry_t
   use model_materials, only: material_table_t
   use be_kelvin, only: be_stiffness, element_influence
   use be_lapack, only: gemv
   implicit none
   private
   public :: be_link, be_ensure, be_step, be_stiffness_bound, be_node_position, be_induced

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
      if (be%half) then
         call half_plane_check(be, x, y, error)
         if (allocated(error)) return
      end if
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

   !> BE HALF: the far field is the half plane y < 0 (manual Section 4.5,
   !> "assuming surface at y = 0"): no node above the surface, no element
   !> lying in it (its image would coincide with it). Tolerance: 1e-6 of the
   !> extent of the elements.
   subroutine half_plane_check(be, x, y, error)
      type(be_t), intent(in) :: be
      real(wp), intent(in) :: x(:), y(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: tol
      integer(ip) :: i, e
      character(len=160) :: text
      tol = 1.0e-6_wp*max(maxval(x) - minval(x), maxval(y) - minval(y), tiny(1.0_wp))
      do i = 1, be%nc
         if (y(i) > tol) then
            write (text, '(a,i0,a,i0,a)') 'BE STIFFNESS: BE HALF puts the ground surface at ' &
               //'y = 0, but node ', i, ' (corner ', be%corner(i), ') lies above it at y = '
            call set_error(error, trim(text)//' '//format_real(y(i))//' (nothing linked)')
            return
         end if
      end do
      if (be%fix .and. (be%yh > tol .or. be%yv > tol)) then
         call set_error(error, 'BE STIFFNESS: BE HALF puts the ground surface at y = 0; the ' &
                        //'BE FIX points must lie in the far field below it, y <= 0 (nothing ' &
                        //'linked)')
         return
      end if
      do e = 1, be%ne
         if (y(be%ea(e)) > -tol .and. y(be%eb(e)) > -tol) then
            write (text, '(a,i0,a)') 'BE STIFFNESS: element ', e, ' lies in the ground ' &
               //'surface y = 0 of BE HALF; the surface is free, generate the elements below ' &
               //'it only (nothing linked)'
            call set_error(error, trim(text))
            return
         end if
      end do
   end subroutine half_plane_check

   subroutine build(be, x, y, shear, nu, k, error, sol)
      type(be_t), intent(in) :: be
      real(wp), intent(in) :: x(:), y(:), shear, nu
      real(wp), allocatable, intent(out) :: k(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable, intent(out), optional :: sol(:, :)
      call be_stiffness(x, y, int(be%ea(1:be%ne)), int(be%eb(1:be%ne)), shear, nu, be%fix, &
                        be%xh, be%yh, be%xv, be%yv, k, error, half=be%half, sol=sol)
      if (allocated(error)) error%message = 'BE STIFFNESS: '//error%message
   end subroutine build

   !> Induced displacement u(2, n) and stress s(3, n) (sxx, syy, sxy) of the
   !> far field at the points (px, py) (PRINT BEBOUND, BEINT; manual Section
   !> 4.5: "induced values - not total values"): the fictitious tractions of
   !> the node displacements since the link, from the matrices rebuilt at the
   !> link positions. self(k) > 0: point k is the midpoint of element self(k)
   !> (its stress on the far field's side). The displacement includes the
   !> far field's translation (cx, cy): with BE FIX it is zero at the fixed
   !> points, without, the far field is displaced by (cx, cy) at infinity.
   subroutine be_induced(be, geo, px, py, self, u, s, error)
      type(be_t), intent(in) :: be
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: px(:), py(:)
      integer, intent(in) :: self(:)
      real(wp), intent(out) :: u(:, :), s(:, :)
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: k(:, :), sol(:, :), ud(:), p(:)
      real(wp) :: x, y, l, mx, my, tx, ty, ue(2, 2), se(3, 2)
      integer(ip) :: i, e
      integer :: m
      u = 0.0_wp
      s = 0.0_wp
      if (.not. be%linked) then
         call set_error(error, 'the boundary-element far field is not linked (BE STIFFNESS)')
         return
      end if
      call build(be, be%x0, be%y0, be%g, be%nu, k, error, sol)
      if (allocated(error)) return
      allocate (ud(2*be%nc))
      do i = 1, be%nc
         call be_node_position(be, geo, i, x, y)
         ud(2*i - 1) = x - be%x0(i)
         ud(2*i) = y - be%y0(i)
      end do
      p = matmul(sol, ud)
      do m = 1, size(px)
         u(:, m) = p(2*be%ne + 1:2*be%ne + 2)
      end do
      do e = 1, be%ne
         associate (xa => be%x0(be%ea(e)), ya => be%y0(be%ea(e)), xb => be%x0(be%eb(e)), &
                    yb => be%y0(be%eb(e)))
            l = hypot(xb - xa, yb - ya)
            mx = 0.5_wp*(xa + xb); my = 0.5_wp*(ya + yb)
            tx = (xb - xa)/l; ty = (yb - ya)/l
         end associate
         do m = 1, size(px)
            call element_influence(px(m), py(m), mx, my, tx, ty, 0.5_wp*l, be%g, be%nu, &
                                   self(m) == e, ue, se, be%half)
            u(:, m) = u(:, m) + matmul(ue, p(2*e - 1:2*e))
            s(:, m) = s(:, m) + matmul(se, p(2*e - 1:2*e))
         end do
      end do
   end subroutine be_induced

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
