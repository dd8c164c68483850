!> BE (manual Section 4.5): the boundary-element far field. Keywords on one
!> line act in the manual's recommended order whatever order they are typed
!> in: GEN, MAT, HALF, FIX, STIFFNESS. Everything is checked before anything
!> changes. The far field itself: src/be (be_kelvin, be_far_field).
!>
!>   BE GEN <x1 x2 y1 y2>     elements on the free block edges whose two
!>                            corners lie in the range (the whole outer
!>   BE GEN CORNER ic1 ic2    boundary without one); or on the boundary walked
!>                            clockwise from corner ic1 to ic2
!>   BE MAT n                 far-field K and G from material n
!>   BE FIX xh yh xv yv       the far field does not move in x at (xh, yh)
!>                            nor in y at (xv, yv)
!>   BE HALF                  the far field is the half plane y < 0 with a
!>                            free ground surface y = 0 (be_halfplane)
!>   BE STIFFNESS             builds the matrix and links the far field
!>
!> PRINT BE (and PRINT BOUNDARY BE) lists the nodes with their displacement
!> since the link and the force the far field puts on them; PRINT BEBOUND
!> the induced displacement and stress at the element midpoints, PRINT
!> BEINT n x1 y1 x2 y2 at n points of a line in the far field.
module commands_be
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use core_output, only: output_t, fmt_real, format_real
   use model_state, only: model_t
   use model_be, only: be_t, be_clear_link
   use zones_boundary_setup, only: block_grid_t, block_grid_build, boundary_extend, &
                                   boundary_walk, corner_free_sides
   use model_boundary, only: boundary_t
   use model_geometry, only: geometry_t
   use contact_refresh, only: geometry_refresh
   use be_far_field, only: be_link, be_node_position, be_induced
   use commands_parser, only: parsed_t
   use commands_context, only: context_t, registry_t, require_block
   implicit none
   private
   public :: register_be_commands
   public :: do_be, be_print, be_print_bebound, be_print_beint

contains

   !> The commands of this family in the registry (commands_context).
   subroutine register_be_commands(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('be', 'BE', '', '', 'Fix rrrr;Half;Gen [rrrr];Corner ii;Mat q;Stiffness', &
                   '4.5', 'boundary-element far field around the block model', handler=do_be)
   end subroutine register_be_commands

   subroutine do_be(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      type(be_t) :: be
      integer :: kg, kc, km, kf, kh, ks
      character(len=200) :: text
      associate (model => ctx%model, out => ctx%out)
         kg = parsed%find('GEN')
         kc = parsed%find('CORNER')
         km = parsed%find('MAT')
         kf = parsed%find('FIX')
         kh = parsed%find('HALF')
         ks = parsed%find('STIFFNESS')
         if (kg + kc + km + kf + kh + ks == 0) then
            call set_error(error, 'BE: expected a keyword: GEN, MAT, HALF, FIX or STIFFNESS')
            return
         end if
         if (kc > 0 .and. kg == 0) then
            call set_error(error, 'BE CORNER: give it after GEN (BE GEN CORNER ic1 ic2)')
            return
         end if
         if (kg > 0 .and. kc > 0) then
            if (parsed%items(kg)%count > 0) then
               call set_error(error, 'BE GEN: give either a range x1 x2 y1 y2 or CORNER ic1 ic2, ' &
                              //'not both')
               return
            end if
         end if
         call require_block(model, 'BE', error)
         if (allocated(error)) return
         be = model%be
         ! corner positions and the free-surface test want up-to-date blocks
         if (kg > 0 .or. ks > 0) call geometry_refresh(model%geometry)
         if (kg > 0) then
            call generate(model, parsed, kg, kc, be, error)
            if (allocated(error)) return
         end if
         if (km > 0) then
            if (parsed%int_at(km, 1) < 1 .or. parsed%int_at(km, 1) > model%materials%nmat) then
               write (text, '(a,i0,a,i0,a)') 'BE MAT: material ', parsed%int_at(km, 1), &
                  ' is not defined (PROPERTY MAT= defines 1 to ', model%materials%nmat, ')'
               call set_error(error, trim(text))
               return
            end if
            be%mat = parsed%int_at(km, 1)
         end if
         if (kh > 0) be%half = .true.
         if (kf > 0) then
            be%fix = .true.
            be%xh = parsed%real_at(kf, 1)
            be%yh = parsed%real_at(kf, 2)
            be%xv = parsed%real_at(kf, 3)
            be%yv = parsed%real_at(kf, 4)
         end if
         if (ks > 0) then
            if (be%ne == 0) then
               call set_error(error, 'BE STIFFNESS: no boundary elements (give BE GEN first)')
               return
            end if
            if (be%mat == 0) then
               call set_error(error, 'BE STIFFNESS: no far-field material (give BE MAT n first)')
               return
            end if
            if (be%half) call drop_surface_elements(be, model, out)
            call be_link(be, model%geometry, model%materials, error)
            if (allocated(error)) return
         end if
         ! accepted: report and keep
         if (kg > 0) then
            write (text, '(a,i0,a,i0,a)') 'BE GEN: ', be%ne, ' boundary element(s) on ', be%nc, &
               ' corner(s)'
            call out%line(trim(text))
            if (model%be%linked) call out%line('BE GEN: the far field linked before is removed; ' &
                                               //'give BE STIFFNESS to link the new one')
         end if
         if (ks > 0) then
            write (text, '(a,i0,a)') 'BE STIFFNESS: far field linked on ', be%ne, &
               ' element(s), G = '
            call out%line(trim(text)//' '//format_real(be%g)//', nu = '//format_real(be%nu)// &
                          trim(merge(' (BE FIX points)', '                ', be%fix))// &
                          trim(merge(' half plane y < 0', '                 ', be%half)))
         end if
         model%be = be
      end associate
   end subroutine do_be

   !> BE HALF: the ground surface y = 0 is free, so elements lying in it
   !> (both corners within 1e-6 of the model's extent of y = 0) are not part
   !> of the far field; they are dropped with a note.
   subroutine drop_surface_elements(be, model, out)
      type(be_t), intent(inout) :: be
      type(model_t), intent(in) :: model
      type(output_t), intent(inout) :: out
      integer(ip) :: e, m
      real(wp) :: tol, ya, yb, x
      character(len=160) :: text
      tol = 1.0e-6_wp*max(maxval(model%geometry%corners%y(1:model%geometry%corners%n)) - &
                          minval(model%geometry%corners%y(1:model%geometry%corners%n)), &
                          tiny(1.0_wp))
      m = 0
      do e = 1, be%ne
         call be_node_position(be, model%geometry, be%ea(e), x, ya)
         call be_node_position(be, model%geometry, be%eb(e), x, yb)
         if (abs(ya) <= tol .and. abs(yb) <= tol) cycle
         m = m + 1
         be%ea(m) = be%ea(e)
         be%eb(m) = be%eb(e)
      end do
      if (m < be%ne .and. m > 0) then
         write (text, '(a,i0,a)') 'BE HALF: ', be%ne - m, ' element(s) lying in the free ' &
            //'ground surface y = 0 are not part of the far field'
         call out%line(trim(text))
         be%ne = m
      end if
   end subroutine drop_surface_elements

   !> BE GEN: the elements into `be` (its link is cleared).
   subroutine generate(model, parsed, kg, kc, be, error)
      type(model_t), intent(inout) :: model
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: kg, kc
      type(be_t), intent(inout) :: be
      type(error_t), allocatable, intent(out) :: error
      type(block_grid_t) :: grid
      type(boundary_t) :: bnd
      logical, allocatable :: csel(:), sel(:)
      integer(ip), allocatable :: node(:), ca(:), cb(:)
      integer(ip) :: b, c, nx, i, k, ne, nc, ncorner
      real(wp) :: x1, x2, y1, y2
      logical :: fp, fn, ranged
      associate (geo => model%geometry, co => model%geometry%corners)
         call block_grid_build(geo, grid)
         ncorner = co%n
         allocate (csel(max(1_ip, ncorner)))
         csel = .false.
         if (kc > 0) then
            bnd = model%bound
            call boundary_extend(bnd, geo, grid, k)
            allocate (sel(max(1_ip, bnd%n)))
            call boundary_walk(bnd, geo, grid, int(parsed%int_at(kc, 1), ip), &
                               int(parsed%int_at(kc, 2), ip), sel(1:bnd%n), error)
            if (allocated(error)) then
               error%message = 'BE GEN '//error%message
               return
            end if
            do i = 1, bnd%n
               if (sel(i)) csel(bnd%corner(i)) = .true.
            end do
         else
            ranged = parsed%items(kg)%count == 4
            if (ranged) then
               x1 = parsed%real_at(kg, 1); x2 = parsed%real_at(kg, 2)
               y1 = parsed%real_at(kg, 3); y2 = parsed%real_at(kg, 4)
            end if
            do c = 1, ncorner
               if (.not. co%live(c)) cycle
               if (ranged) csel(c) = co%x(c) > x1 .and. co%x(c) < x2 .and. &
                                     co%y(c) > y1 .and. co%y(c) < y2
               if (.not. ranged) csel(c) = .true.
            end do
         end if
         ! elements: free edges c -> next(c) of live blocks with both ends selected
         allocate (ca(max(1_ip, ncorner)), cb(max(1_ip, ncorner)), node(max(1_ip, ncorner)))
         node = 0
         ne = 0
         nc = 0
         do b = 1, geo%blocks%n
            if (.not. geo%blocks%live(b)) cycle
            c = geo%blocks%first_corner(b)
            do i = 1, geo%blocks%ncorner(b)
               nx = co%next(c)
               if (csel(c) .and. csel(nx)) then
                  call corner_free_sides(geo, grid, c, fp, fn)
                  if (fn) then
                     ne = ne + 1
                     ca(ne) = c
                     cb(ne) = nx
                     do k = 1, 2
                        associate (cc => merge(c, nx, k == 1))
                           if (node(cc) == 0) then
                              nc = nc + 1
                              node(cc) = nc
                           end if
                        end associate
                     end do
                  end if
               end if
               c = nx
            end do
         end do
         if (ne == 0) then
            if (kc > 0) then
               call set_error(error, 'BE GEN CORNER: no free block edge lies between the two ' &
                              //'corners')
            else
               call set_error(error, 'BE GEN: no free block edge has both corners in the range')
            end if
            return
         end if
         call be_clear_link(be)
         be%ne = ne
         be%nc = nc
         allocate (be%corner(nc), be%ea(ne), be%eb(ne))
         do c = 1, ncorner
            if (node(c) > 0) be%corner(node(c)) = c
         end do
         do i = 1, ne
            be%ea(i) = node(ca(i))
            be%eb(i) = node(cb(i))
         end do
      end associate
   end subroutine generate

   !> PRINT BE: the nodes of the far field.
   subroutine be_print(model, out)
      type(model_t), intent(inout) :: model
      type(output_t), intent(inout) :: out
      integer(ip) :: i
      real(wp) :: x, y, ux, uy, fx, fy
      character(len=200) :: line
      associate (be => model%be)
         if (be%ne == 0) then
            call out%line('No boundary elements (BE GEN).')
            return
         end if
         write (line, '(a,i0,a,i0,a,i0,a)') 'Boundary-element far field: ', be%ne, &
            ' element(s), ', be%nc, ' node(s), material ', be%mat, &
            merge(', linked    ', ', not linked', be%linked)
         call out%line(trim(line))
         call out%line('    NODE  CORNER             X             Y         X-DISP' // &
                       '         Y-DISP        X-FORCE        Y-FORCE')
         do i = 1, be%nc
            call be_node_position(be, model%geometry, i, x, y)
            ux = 0.0_wp; uy = 0.0_wp; fx = 0.0_wp; fy = 0.0_wp
            if (be%linked) then
               ux = x - be%x0(i)
               uy = y - be%y0(i)
               if (allocated(be%f)) then
                  fx = be%f(2*i - 1)
                  fy = be%f(2*i)
               end if
            end if
            write (line, '(i8,i8,6a)') i, be%corner(i), fmt_real(x), fmt_real(y), &
               ' '//fmt_real(ux), ' '//fmt_real(uy), ' '//fmt_real(fx), ' '//fmt_real(fy)
            call out%line(trim(line))
         end do
      end associate
   end subroutine be_print

   !> The far field is linked; else says so (PRINT BEBOUND / BEINT have
   !> nothing to show).
   logical function be_linked(be, out) result(linked)
      type(be_t), intent(in) :: be
      type(output_t), intent(inout) :: out
      linked = be%linked
      if (.not. linked) &
         call out%line('No boundary-element far field is linked (BE GEN, BE MAT, BE STIFFNESS).')
   end function be_linked

   !> be_induced at the points (px, py) into u, s; on failure says so for
   !> `what` and is .false.
   logical function induced(be, geo, px, py, self, u, s, what, out) result(ok)
      type(be_t), intent(in) :: be
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: px(:), py(:)
      integer, intent(in) :: self(:)
      real(wp), intent(out) :: u(:, :), s(:, :)
      character(len=*), intent(in) :: what
      type(output_t), intent(inout) :: out
      type(error_t), allocatable :: error
      call be_induced(be, geo, px, py, self, u, s, error)
      ok = .not. allocated(error)
      if (.not. ok) call out%line('*** '//what//': '//error%message)
   end function induced

   !> PRINT BEBOUND: at each element midpoint the induced displacement and
   !> stress of the far field (its side of the element) since the link.
   subroutine be_print_bebound(model, out)
      type(model_t), intent(inout) :: model
      type(output_t), intent(inout) :: out
      real(wp), allocatable :: px(:), py(:), u(:, :), s(:, :)
      integer, allocatable :: self(:)
      integer(ip) :: e
      character(len=200) :: line
      if (.not. be_linked(model%be, out)) return
      associate (be => model%be)
         allocate (px(be%ne), py(be%ne), self(be%ne), u(2, be%ne), s(3, be%ne))
         do e = 1, be%ne
            px(e) = 0.5_wp*(be%x0(be%ea(e)) + be%x0(be%eb(e)))
            py(e) = 0.5_wp*(be%y0(be%ea(e)) + be%y0(be%eb(e)))
            self(e) = int(e)
         end do
         if (.not. induced(be, model%geometry, px, py, self, u, s, 'PRINT BEBOUND', out)) return
         call out%line('Boundary elements: induced values since BE STIFFNESS (not totals), ' // &
                       trim(merge('half plane y < 0', 'infinite plane  ', be%half)))
         call out%line(' ELEMENT  NODE1  NODE2             X             Y         X-DISP' // &
                       '         Y-DISP            SXX            SYY            SXY')
         do e = 1, be%ne
            write (line, '(i8,2i7,7a)') e, be%ea(e), be%eb(e), fmt_real(px(e)), fmt_real(py(e)), &
               ' '//fmt_real(u(1, e)), ' '//fmt_real(u(2, e)), ' '//fmt_real(s(1, e)), &
               ' '//fmt_real(s(2, e)), ' '//fmt_real(s(3, e))
            call out%line(trim(line))
         end do
      end associate
   end subroutine be_print_bebound

   !> PRINT BEINT n x1 y1 x2 y2: induced displacement and stress at n points
   !> evenly spaced from (x1, y1) to (x2, y2) in the far field.
   subroutine be_print_beint(model, n, x1, y1, x2, y2, out)
      type(model_t), intent(inout) :: model
      integer, intent(in) :: n
      real(wp), intent(in) :: x1, y1, x2, y2
      type(output_t), intent(inout) :: out
      real(wp), allocatable :: px(:), py(:), u(:, :), s(:, :)
      integer, allocatable :: self(:)
      integer :: i
      real(wp) :: t
      character(len=200) :: line
      if (.not. be_linked(model%be, out)) return
      associate (be => model%be)
         allocate (px(n), py(n), self(n), u(2, n), s(3, n))
         self = 0
         do i = 1, n
            t = 0.0_wp
            if (n > 1) t = real(i - 1, wp)/real(n - 1, wp)
            px(i) = x1 + t*(x2 - x1)
            py(i) = y1 + t*(y2 - y1)
         end do
         if (.not. induced(be, model%geometry, px, py, self, u, s, 'PRINT BEINT', out)) return
         call out%line('Boundary-element domain: induced values since BE STIFFNESS (not ' // &
                       'totals) at points in the far field')
         if (be%half) call out%line('(half plane: points above the surface y = 0 are not in ' // &
                                    'the far field and are not printed)')
         call out%line('   POINT             X             Y         X-DISP         Y-DISP' // &
                       '            SXX            SYY            SXY')
         do i = 1, n
            if (be%half .and. py(i) > 0.0_wp) cycle
            write (line, '(i8,7a)') i, fmt_real(px(i)), fmt_real(py(i)), ' '//fmt_real(u(1, i)), &
               ' '//fmt_real(u(2, i)), ' '//fmt_real(s(1, i)), ' '//fmt_real(s(2, i)), &
               ' '//fmt_real(s(3, i))
            call out%line(trim(line))
         end do
      end associate
   end subroutine be_print_beint

end module commands_be
