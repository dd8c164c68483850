!> EXPORT (an extension, issue 24): the model for ParaView and the histories
!> for spreadsheets.
!>
!>   EXPORT name.vtu        VTK XML UnstructuredGrid, ASCII, one piece whose
!>                          cells are the block polygons (cell kind 1), the
!>                          zones (kind 2) and the contacts as line segments
!>                          (kind 3, centred on the contact point, its length
!>                          along the tangent); the cell array `kind` tells
!>                          them apart (ParaView: Threshold on kind).
!>   EXPORT HISTORY name.csv  every history as a column, with a header row
!>                          naming it, where it is measured and its unit; the
!>                          first columns are the cycle and the time.
!>
!> Cell data (0 where a quantity does not apply): kind, id (block, zone or
!> contact id), material (block material; the zone's block material; the
!> contact's JMAT), state (zone plasticity indicator as PRINT ZONE STATE;
!> contact state bits as PRINT CONTACT STATE), velocity and displacement
!> (block centroid; a zone's mean of its gridpoints) [m/s, m], sxx syy sxy
!> szz (zones, tension positive) [Pa], normal_force shear_force (contacts,
!> compression positive) [N], aperture (contacts: the hydraulic aperture of
!> the last flow step when the model has joint fluid, otherwise the opening
!> max(gap, 0)) [m], and with joint fluid pore_pressure (contacts: the mean
!> pressure of the domains either side) [Pa]. Point data: velocity and
!> displacement of corners (rigid-block motion at the corner, or the corner's
!> gridpoint) and gridpoints, and with heat conduction the gridpoints'
!> temperature. Files are written to a temporary and renamed into place,
!> after the project's output-file checks (core_files).
module commands_export
   use core_kinds, only: wp, ip, i8
   use core_error, only: error_t, set_error
   use core_output, only: output_t, fmt_real, itoa
   use core_files, only: check_output_file, temporary_name, file_rename, file_delete
   use model_state, only: model_t
   use model_history, only: hist_keyword, history_first, hist_damp, hist_unit
   use commands_parser, only: parsed_t
   use commands_context, only: context_t, registry_t
   use commands_tokens, only: to_lower, substituted
   implicit none
   private
   public :: register_export_commands, export_vtu, export_history_csv, history_unit

   integer, parameter :: kind_block = 1, kind_zone = 2, kind_contact = 3
   integer, parameter :: vtk_line = 3, vtk_triangle = 5, vtk_polygon = 7

contains

   !> The commands of this family in the registry (commands_context).
   subroutine register_export_commands(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('export', 'EXPort', '[s]', '', 'History s', 'udec', &
                   'extension: write the model for ParaView (name.vtu) or every history ' // &
                   'as a CSV column (HISTORY name.csv)', run_export)
   end subroutine register_export_commands

   subroutine run_export(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: file
      integer :: k
      k = parsed%find('HISTORY')
      if (k > 0) then
         if (parsed%items(1)%name == '' .and. parsed%items(1)%count > 0) then
            call set_error(error, 'EXPORT: give either a .vtu file or HISTORY name.csv, not both')
            return
         end if
         file = parsed%text_at(k, 1)
         call export_history_csv(ctx%model, file, error)
         if (allocated(error)) return
         call ctx%out%line("EXPORT: "//itoa(ctx%model%hist%n)//" histories, "// &
                           itoa(int(ctx%model%hist%nsample))//" samples written to '"//file//"'")
         return
      end if
      if (parsed%nitems < 1 .or. parsed%items(1)%name /= '' .or. parsed%items(1)%count < 1) then
         call set_error(error, 'EXPORT: expected a file name ending in .vtu, or HISTORY name.csv')
         return
      end if
      file = parsed%text_at(1, 1)
      if (len(file) < 5) then
         call set_error(error, "EXPORT: expected a file name ending in .vtu, got '"//file//"'")
         return
      end if
      if (to_lower(file(len(file) - 3:)) /= '.vtu') then
         call set_error(error, "EXPORT: expected a file name ending in .vtu (VTK XML "// &
                        "unstructured grid), got '"//file//"'")
         return
      end if
      call export_vtu(ctx%model, file, ctx%out, error)
   end subroutine run_export

   !> The unit of a history kind's values (SI, per metre out of plane).
   pure function history_unit(kind) result(unit)
      integer, intent(in) :: kind
      character(len=:), allocatable :: unit
      ! as plot axes read them (hist_unit), but for the damping ratio's
      ! 1/s and '-' where a plot leaves the unit blank
      unit = trim(hist_unit(kind))
      if (kind == hist_damp) unit = '1/s'
      if (unit == '') unit = '-'
   end function history_unit

   !> EXPORT HISTORY file: cycle, time, then one column per history; a
   !> history defined after samples were taken has empty cells before its
   !> first sample.
   subroutine export_history_csv(model, file, error)
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: file
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: tmp, header, row
      integer :: u, ios, h
      integer(ip) :: s
      if (model%hist%n == 0) then
         call set_error(error, 'EXPORT HISTORY: there are no histories (give HISTORY first)')
         return
      end if
      call start_file('EXPORT HISTORY', file, tmp, u, error)
      if (allocated(error)) return
      associate (hist => model%hist)
         header = 'cycle,time [s]'
         do h = 1, hist%n
            header = header//','//itoa(h)//' '//trim(hist_keyword(hist%kind(h)))
            if (hist%entity(h) > 0) header = header//' '//itoa(int(hist%entity(h)))// &
                                             ' at ('//trim(adjustl(fmt_real(hist%px(h), 12, 5)))// &
                                             ' '//trim(adjustl(fmt_real(hist%py(h), 12, 5)))//')'
            header = header//' ['//history_unit(hist%kind(h))//']'
         end do
         write (u, '(a)', iostat=ios) header
         do s = 1, hist%nsample
            row = itoa(int(hist%step(s), i8))//','//num(hist%time(s))
            do h = 1, hist%n
               if (s < history_first(hist, h)) then
                  row = row//','
               else
                  row = row//','//num(hist%values(h, s))
               end if
            end do
            if (ios == 0) write (u, '(a)', iostat=ios) row
         end do
      end associate
      close (u)
      call finish_file('EXPORT HISTORY', tmp, file, ios, error)
   end subroutine export_history_csv

   !> EXPORT name.vtu (module header).
   subroutine export_vtu(model, file, out, error)
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: file
      type(output_t), intent(inout) :: out
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: tmp
      integer :: u, ios
      integer(ip) :: nc, ng, ncon, nb, nz, npts, ncells, b, c, z, k, g, m
      integer(ip), allocatable :: cons(:), live_z(:)
      call start_file('EXPORT', file, tmp, u, error)
      if (allocated(error)) return
      associate (geo => model%geometry, bl => model%geometry%blocks, co => model%geometry%corners, &
                 gp => model%geometry%gridpoints, zn => model%geometry%zones, &
                 ct => model%geometry%contacts)
         nc = co%n
         ng = gp%n
         nb = count(bl%live(1:bl%n))
         nz = count(zn%live(1:zn%n))
         live_z = pack([(z, z=1, zn%n)], zn%live(1:zn%n))
         ! contacts: the live ones, in id order
         cons = pack([(c, c=1, ct%n)], ct%live(1:ct%n))
         ncon = size(cons, kind=ip)
         npts = nc + ng + 2*ncon
         ncells = nb + nz + ncon
         write (u, '(a)') '<?xml version="1.0"?>', &
            '<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">', &
            '<UnstructuredGrid>'
         if (len(model%heading) > 0) write (u, '(a)') '<!-- '//xml_text(model%heading)//' -->'
         write (u, '(a)') '<Piece NumberOfPoints="'//itoa(int(npts))//'" NumberOfCells="'// &
            itoa(int(ncells))//'">'
         ! points: corners, gridpoints, two ends of every contact segment
         write (u, '(a)') '<Points>', &
            '<DataArray type="Float64" NumberOfComponents="3" format="ascii">'
         call put_vectors(co%x(1:nc), co%y(1:nc))
         call put_vectors(gp%x(1:ng), gp%y(1:ng))
         do k = 1, ncon
            c = cons(k)
            write (u, '(a)') num(ct%x(c) + 0.5_wp*ct%length(c)*ct%ny(c))//' '// &
               num(ct%y(c) - 0.5_wp*ct%length(c)*ct%nx(c))//' 0'
            write (u, '(a)') num(ct%x(c) - 0.5_wp*ct%length(c)*ct%ny(c))//' '// &
               num(ct%y(c) + 0.5_wp*ct%length(c)*ct%nx(c))//' 0'
         end do
         write (u, '(a)') '</DataArray>', '</Points>', '<Cells>', &
            '<DataArray type="Int64" Name="connectivity" format="ascii">'
         do b = 1, bl%n
            if (.not. bl%live(b)) cycle
            call write_ring(b)
         end do
         do z = 1, zn%n
            if (.not. zn%live(z)) cycle
            write (u, '(a)') itoa(int(nc + zn%g1(z) - 1))//' '//itoa(int(nc + zn%g2(z) - 1))//' '// &
               itoa(int(nc + zn%g3(z) - 1))
         end do
         do k = 1, ncon
            write (u, '(a)') itoa(int(nc + ng + 2*(k - 1)))//' '//itoa(int(nc + ng + 2*k - 1))
         end do
         write (u, '(a)') '</DataArray>', '<DataArray type="Int64" Name="offsets" format="ascii">'
         m = 0
         do b = 1, bl%n
            if (.not. bl%live(b)) cycle
            m = m + ring_size(b)
            write (u, '(a)') itoa(int(m))
         end do
         do z = 1, zn%n
            if (.not. zn%live(z)) cycle
            m = m + 3
            write (u, '(a)') itoa(int(m))
         end do
         do k = 1, ncon
            m = m + 2
            write (u, '(a)') itoa(int(m))
         end do
         write (u, '(a)') '</DataArray>', '<DataArray type="UInt8" Name="types" format="ascii">'
         call put_ints(nb, vtk_polygon)
         call put_ints(nz, vtk_triangle)
         call put_ints(ncon, vtk_line)
         write (u, '(a)') '</DataArray>', '</Cells>'

         ! cell data, in the order blocks, zones, contacts
         write (u, '(a)') '<CellData Scalars="kind">'
         call open_array('Int32', 'kind', 1)
         call put_ints(nb, kind_block)
         call put_ints(nz, kind_zone)
         call put_ints(ncon, kind_contact)
         call close_array()
         call open_array('Int32', 'id', 1)
         call put_ints_of(pack([(b, b=1, bl%n)], bl%live(1:bl%n)))
         call put_ints_of(pack([(z, z=1, zn%n)], zn%live(1:zn%n)))
         call put_ints_of(cons)
         call close_array()
         call open_array('Int32', 'material', 1)
         call put_ints_of(pack(bl%material(1:bl%n), bl%live(1:bl%n)))
         call put_ints_of([(bl%material(zn%block(live_z(k))), k=1, nz)])
         call put_ints_of(ct%jmat(cons))
         call close_array()
         call open_array('Int32', 'state', 1)
         call put_ints(nb, 0)
         call put_ints_of(pack(zn%state(1:zn%n), zn%live(1:zn%n)))
         call put_ints_of(int(ct%state%flags(cons), ip))
         call close_array()
         call cell_vectors('velocity', bl%vx, bl%vy, gp%vx, gp%vy)
         call cell_vectors('displacement', bl%ux, bl%uy, gp%ux, gp%uy)
         call zone_array('sxx', zn%sxx)
         call zone_array('syy', zn%syy)
         call zone_array('sxy', zn%sxy)
         call zone_array('szz', zn%szz)
         call contact_array('normal_force', ct%state%fn(cons))
         call contact_array('shear_force', ct%state%fs(cons))
         call contact_array('aperture', [(contact_aperture(cons(k)), k=1, ncon)])
         if (allocated(model%fluid)) &
            call contact_array('pore_pressure', [(contact_pressure(cons(k)), k=1, ncon)])
         write (u, '(a)') '</CellData>'

         ! point data: corners, gridpoints, contact ends
         write (u, '(a)') '<PointData>'
         call open_array('Float64', 'velocity', 3)
         do k = 1, nc
            write (u, '(a)') corner_velocity(k)
         end do
         call put_vectors(gp%vx(1:ng), gp%vy(1:ng))
         call put_reals(2*ncon, '0 0 0')
         call close_array()
         call open_array('Float64', 'displacement', 3)
         call put_vectors(co%ux(1:nc), co%uy(1:nc))
         call put_vectors(gp%ux(1:ng), gp%uy(1:ng))
         call put_reals(2*ncon, '0 0 0')
         call close_array()
         if (allocated(model%thermal)) then
            call open_array('Float64', 'temperature', 1)
            do k = 1, nc
               g = 0
               if (allocated(co%gp)) g = co%gp(k)
               write (u, '(a)') num(gp_temperature(g))
            end do
            do g = 1, ng
               write (u, '(a)') num(gp_temperature(g))
            end do
            call put_reals(2*ncon, '0')
            call close_array()
         end if
         write (u, '(a)') '</PointData>', '</Piece>', '</UnstructuredGrid>', '</VTKFile>'
         flush (u, iostat=ios)
         close (u)
         call finish_file('EXPORT', tmp, file, ios, error)
         if (allocated(error)) return
         call out%line("EXPORT: "//itoa(int(nb))//" blocks, "//itoa(int(nz))//" zones, "// &
                       itoa(int(ncon))//" contacts written to '"//file//"'")
      end associate

   contains

      integer(ip) function ring_size(b)
         integer(ip), intent(in) :: b
         ring_size = model%geometry%blocks%ncorner(b)
      end function ring_size

      !> The corners of block b, in the ring's order, as point ids.
      subroutine write_ring(b)
         integer(ip), intent(in) :: b
         character(len=:), allocatable :: line
         integer(ip) :: c0, cc, i
         associate (bl => model%geometry%blocks, co => model%geometry%corners)
            c0 = bl%first_corner(b)
            cc = c0
            line = ''
            do i = 1, bl%ncorner(b)
               line = line//' '//itoa(int(cc - 1))
               cc = co%next(cc)
            end do
            write (u, '(a)') line(2:)
         end associate
      end subroutine write_ring

      subroutine open_array(type, name, ncomp)
         character(len=*), intent(in) :: type, name
         integer, intent(in) :: ncomp
         write (u, '(a)') '<DataArray type="'//type//'" Name="'//name// &
            '" NumberOfComponents="'//itoa(ncomp)//'" format="ascii">'
      end subroutine open_array

      subroutine close_array()
         write (u, '(a)') '</DataArray>'
      end subroutine close_array

      subroutine put_ints(n, value)
         integer(ip), intent(in) :: n
         integer, intent(in) :: value
         integer(ip) :: i
         do i = 1, n
            write (u, '(a)') itoa(value)
         end do
      end subroutine put_ints

      subroutine put_reals(n, text)
         integer(ip), intent(in) :: n
         character(len=*), intent(in) :: text
         integer(ip) :: i
         do i = 1, n
            write (u, '(a)') text
         end do
      end subroutine put_reals

      subroutine put_ints_of(values)
         integer(ip), intent(in) :: values(:)
         integer(ip) :: i
         do i = 1, size(values, kind=ip)
            write (u, '(a)') itoa(int(values(i)))
         end do
      end subroutine put_ints_of

      !> One line "x y 0" per entry.
      subroutine put_vectors(x, y)
         real(wp), intent(in) :: x(:), y(:)
         integer(ip) :: i
         do i = 1, size(x, kind=ip)
            write (u, '(a)') num(x(i))//' '//num(y(i))//' 0'
         end do
      end subroutine put_vectors

      !> A cell array of zone values (values by zone id): 0 on blocks and contacts.
      subroutine zone_array(name, values)
         character(len=*), intent(in) :: name
         real(wp), intent(in) :: values(:)
         call open_array('Float64', name, 1)
         call put_reals(nb, '0')
         call put_values(values(live_z))
         call put_reals(ncon, '0')
         call close_array()
      end subroutine zone_array

      !> A cell array of contact values (in the order of `cons`): 0 on blocks and zones.
      subroutine contact_array(name, values)
         character(len=*), intent(in) :: name
         real(wp), intent(in) :: values(:)
         call open_array('Float64', name, 1)
         call put_reals(nb + nz, '0')
         call put_values(values)
         call close_array()
      end subroutine contact_array

      subroutine put_values(values)
         real(wp), intent(in) :: values(:)
         integer(ip) :: i
         do i = 1, size(values, kind=ip)
            write (u, '(a)') num(values(i))
         end do
      end subroutine put_values

      !> A cell array of vectors: the blocks' (bx, by), the mean over its three
      !> gridpoints of each zone's (gx, gy), 0 on contacts.
      subroutine cell_vectors(name, bx, by, gx, gy)
         character(len=*), intent(in) :: name
         real(wp), intent(in) :: bx(:), by(:), gx(:), gy(:)
         associate (bl => model%geometry%blocks)
            call open_array('Float64', name, 3)
            call put_vectors(pack(bx(1:bl%n), bl%live(1:bl%n)), pack(by(1:bl%n), bl%live(1:bl%n)))
            call put_vectors(zone_means(gx), zone_means(gy))
            call put_reals(ncon, '0 0 0')
            call close_array()
         end associate
      end subroutine cell_vectors

      !> The mean of `values` (by gridpoint) over each live zone's three gridpoints.
      function zone_means(values) result(mean)
         real(wp), intent(in) :: values(:)
         real(wp) :: mean(nz)
         integer(ip) :: k, z
         associate (zn => model%geometry%zones)
            do k = 1, nz
               z = live_z(k)
               mean(k) = (values(zn%g1(z)) + values(zn%g2(z)) + values(zn%g3(z)))/3.0_wp
            end do
         end associate
      end function zone_means

      !> Contact c's aperture: the joint fluid's, else its open gap.
      real(wp) function contact_aperture(c)
         integer(ip), intent(in) :: c
         contact_aperture = max(model%geometry%contacts%gap(c), 0.0_wp)
         if (.not. allocated(model%fluid)) return
         if (c <= model%fluid%nc) contact_aperture = model%fluid%aperture(c)
      end function contact_aperture

      !> A corner's velocity: its gridpoint's, or the rigid motion of its block.
      function corner_velocity(k) result(text)
         integer(ip), intent(in) :: k
         character(len=:), allocatable :: text
         integer(ip) :: b, g
         associate (bl => model%geometry%blocks, co => model%geometry%corners, &
                    gp => model%geometry%gridpoints)
            g = 0
            if (allocated(co%gp)) g = co%gp(k)
            b = co%block(k)
            if (g > 0) then
               text = num(gp%vx(g))//' '//num(gp%vy(g))//' 0'
            else if (co%live(k) .and. b >= 1 .and. b <= bl%n) then
               text = num(bl%vx(b) - bl%vr(b)*(co%y(k) - bl%yc(b)))//' '// &
                      num(bl%vy(b) + bl%vr(b)*(co%x(k) - bl%xc(b)))//' 0'
            else
               text = '0 0 0'
            end if
         end associate
      end function corner_velocity

      real(wp) function gp_temperature(g)
         integer(ip), intent(in) :: g
         gp_temperature = 0.0_wp
         if (g < 1) return
         if (.not. allocated(model%thermal%temp)) return
         if (g > min(model%thermal%ng, size(model%thermal%temp, kind=ip))) return
         gp_temperature = model%thermal%temp(g)
      end function gp_temperature

      !> Mean pressure of the domains either side of contact c (joint fluid).
      real(wp) function contact_pressure(c)
         integer(ip), intent(in) :: c
         integer(ip) :: d1, d2
         integer :: n
         contact_pressure = 0.0_wp
         n = 0
         d1 = model%geometry%contacts%dom1(c)
         d2 = model%geometry%contacts%dom2(c)
         if (d1 >= 1 .and. d1 <= size(model%fluid%p, kind=ip)) then
            contact_pressure = contact_pressure + model%fluid%p(d1)
            n = n + 1
         end if
         if (d2 >= 1 .and. d2 <= size(model%fluid%p, kind=ip)) then
            contact_pressure = contact_pressure + model%fluid%p(d2)
            n = n + 1
         end if
         if (n > 0) contact_pressure = contact_pressure/real(n, wp)
      end function contact_pressure
   end subroutine export_vtu

   !> Check the output file name and open its temporary (unit u) for writing.
   subroutine start_file(command, file, tmp, u, error)
      character(len=*), intent(in) :: command, file
      character(len=:), allocatable, intent(out) :: tmp
      integer, intent(out) :: u
      type(error_t), allocatable, intent(out) :: error
      integer :: ios
      call check_output_file(command, file, error)
      if (allocated(error)) return
      tmp = temporary_name(file)
      open (newunit=u, file=tmp, status='replace', action='write', iostat=ios)
      if (ios /= 0) call set_error(error, command//": cannot write file '"//file//"'")
   end subroutine start_file

   !> Close the temporary and rename it into place; on failure no
   !> temporary is left behind and the old file is untouched.
   subroutine finish_file(command, tmp, file, ios, error)
      character(len=*), intent(in) :: command, tmp, file
      integer, intent(in) :: ios
      type(error_t), allocatable, intent(out) :: error
      logical :: ok
      ok = ios == 0
      if (ok) call file_rename(tmp, file, ok)
      if (.not. ok) then
         call file_delete(tmp)
         call set_error(error, command//": cannot write file '"//file//"'")
      end if
   end subroutine finish_file

   !> A real for the files: 17 significant digits (round trip), readable
   !> by C's strtod and Python's float.
   pure function num(x) result(text)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: text
      character(len=32) :: buf
      write (buf, '(es24.16e3)') x
      text = trim(adjustl(buf))
   end function num

   !> Text safe inside an XML comment.
   pure function xml_text(text) result(safe)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: safe
      safe = substituted(text, '-<>&', '    ', 1)
   end function xml_text

end module commands_export
