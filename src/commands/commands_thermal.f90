!> Thermal commands (manual Section 7.4): THERMAL, INITEM, TFIX, TFREE, THAPP,
!> RUN, the thermal keywords of SET (THDT, NTHER, NMECH) and PRINT
!> TEMPERATURE / PRINT THERMAL. The first of them creates the model's thermal
!> part (model_thermal); a model without it runs no thermal code. Physics:
!> src/thermal/thermal_conduction.f90, the RUN loop src/engine/engine_thermal.f90.
module commands_thermal
   use core_kinds, only: wp, ip, l1
   use core_error, only: error_t, set_error
   use core_files, only: check_output_file, temporary_name, file_rename, file_delete
   use core_output, only: output_t, itoa
   use commands_numbers, only: format_real
   use model_state, only: model_t
   use model_geometry, only: unzoned_block
   use model_zone_fields, only: nearest_gridpoint
   use core_range, only: range_t
   use zones_boundary_setup, only: block_grid_t, block_grid_build, corner_free_sides
   use model_thermal, only: thermal_t, thermal_size, thermal_size_rigid, thermal_add_record, bc_convection, &
                            bc_flux, bc_radiation, bc_source, max_thist
   use thermal_conduction, only: thermal_apply_stress
   use engine_thermal, only: thermal_run
   use commands_parser, only: parsed_t, item_loose
   use model_tables, only: max_tables, table_store, table_value
   use commands_context, only: context_t, registry_t, cannot_fail, require_block
   implicit none
   private
   public :: register_thermal_commands
   public :: set_thermal_keyword
   public :: print_temperatures, print_thermal_conditions, print_thermal_histories, &
             print_boundary_temperatures, print_tables

contains

   !> The commands of this family in the registry (commands_context).
   subroutine register_thermal_commands(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('thermal', 'THERMal', '', '', '', '4.5', &
                   'make heat conduction part of the model (THERM: T is TABLE, TUNNEL)', &
                   run_thermal)
      call reg%add('thermal', 'INITEM', 'rR', '', '', '7.4', &
                   'initial temperature of the gridpoints in a range', handler=do_temperature, &
                   unit='deg C', args='value xl xu yl yu')
      call reg%add('thermal', 'RUN', '', '', 'Age n;CLock n;Delt p;Noage;Temp p;Step q;' // &
                   'Implicit;TOL p', '7.4', 'take thermal steps (and mechanical ones, SET NMECH)', &
                   run_run)
      call reg%note('AGE DELT', unit='s')
      call reg%add('thermal', 'TADD', 'qrrrr', '', '', '7.4', &
                   'add temperatures from a TABLE of radius, increment over an arc', &
                   handler=do_tadd, args='ntab xc yc ang1 ang2')
      call reg%add('thermal', 'TAble', 'q', 'rr', '', '4.5', &
                   'a table of x y pairs, for TADD (TA: T is TABLE, THERMAL or TUNNEL)', &
                   handler=do_table, args='ntab')
      call reg%add('thermal', 'TFIX', 'rR', '', '', '7.4', &
                   'fix the temperature of the gridpoints in a range', handler=do_temperature, &
                   unit='deg C', args='value xl xu yl yu')
      call reg%add('thermal', 'TFREE', 'R', '', '', '7.4', 'free the temperatures TFIX held', &
                   handler=do_temperature)
      call reg%add('thermal', 'THAPP', '[R]', '', 'Convection rr;Flux rr;Radiation rr;' // &
                   'Source rr', '7.4', 'thermal boundary conditions and sources', handler=do_thapp)
      call reg%add('thermal', 'THISt', '', '', 'List;NTCYC q;TYPE q;Write qs;Temperature rr', &
                   '7.4', 'thermal histories', handler=do_thist)
      call reg%add_set('thermal', 'NMECH q;NTHER c;THDT p', act=set_thermal_keyword)
      call reg%note('THDT', unit='s')
      call reg%note('NMECH', default='500')
      call reg%note('NTHER', default='0')
   end subroutine register_thermal_commands

   !> The thermal part, created with its defaults if the model has none, sized
   !> to the current gridpoints.
   subroutine ensure_thermal(model)
      type(model_t), intent(inout) :: model
      if (.not. allocated(model%thermal)) allocate (model%thermal)
      call thermal_size(model%thermal, model%geometry%gridpoints%n)
      call thermal_size_rigid(model%thermal, model%geometry%corners%n, model%geometry%blocks%n)
   end subroutine ensure_thermal

   !> Corner c belongs to a live block without zones (its temperature is the
   !> corner's own, Fig. 7-4).
   logical function rigid_corner(model, c)
      type(model_t), intent(in) :: model
      integer(ip), intent(in) :: c
      integer(ip) :: b
      rigid_corner = .false.
      if (.not. model%geometry%corners%live(c)) return
      b = model%geometry%corners%block(c)
      rigid_corner = unzoned_block(model%geometry, b)
   end function rigid_corner

   !> INITEM value range (no thermal stress), TFIX value range (fixed, the
   !> change induces thermal stress), TFREE range.
   subroutine do_temperature(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: value
      integer(ip) :: g, n, nr, c, b
      logical :: any_stress
      character(len=:), allocatable :: what
      associate (model => ctx%model, out => ctx%out)
         what = parsed%name
         if (.not. parsed%has_range) then
            call set_error(error, what//': expected the range xl xu yl yu (or REG ..) after ' &
                           //merge('the temperature', 'the command    ', what /= 'TFREE'))
            return
         end if
         value = 0.0_wp
         if (what /= 'TFREE') value = parsed%real_at(1, 1)
         call ensure_thermal(model)
         n = 0
         any_stress = .false.
         associate (gp => model%geometry%gridpoints, th => model%thermal)
            do g = 1, gp%n
               if (.not. gp%live(g)) cycle
               if (.not. parsed%range%contains_point(gp%x(g), gp%y(g))) cycle
               n = n + 1
               call set_one(th%temp(g), th%fixed(g), th%dtacc(g))
            end do
         end associate
         ! corners and centroids of blocks without zones ("all corners and
         ! gridpoints in the range", Section 7.4.1; centroids: Section 7.6 kbfix)
         nr = 0
         associate (co => model%geometry%corners, bl => model%geometry%blocks, th => model%thermal)
            do c = 1, co%n
               if (rigid_corner(model, c)) &
                  call set_rigid(co%x(c), co%y(c), th%ctemp(c), th%cfixed(c), th%cdtacc(c))
            end do
            do b = 1, bl%n
               if (unzoned_block(model%geometry, b)) &
                  call set_rigid(bl%xc(b), bl%yc(b), th%btemp(b), th%bfixed(b), th%bdtacc(b))
            end do
         end associate
         if (any_stress) call thermal_apply_stress(model)
         if (nr > 0) then
            call out%line(what//': '//itoa(n)//' gridpoint(s), '//itoa(nr)// &
                          ' corner(s) and centroid(s) of blocks without zones')
         else
            call out%line(what//': '//itoa(n)//' gridpoint(s)')
         end if

      end associate
   contains

      !> The command on the temperature of a corner or centroid at (x, y)
      !> of a block without zones, when (x, y) is in the range.
      subroutine set_rigid(x, y, temp, fixed, dtacc)
         real(wp), intent(in) :: x, y
         real(wp), intent(inout) :: temp, dtacc
         logical, intent(inout) :: fixed
         if (.not. parsed%range%contains_point(x, y)) return
         nr = nr + 1
         call set_one(temp, fixed, dtacc)
      end subroutine set_rigid

      !> The command on one temperature (INITEM sets it; TFIX sets and fixes
      !> it, the change accumulating for the thermal stress; TFREE frees it).
      subroutine set_one(temp, fixed, dtacc)
         real(wp), intent(inout) :: temp, dtacc
         logical, intent(inout) :: fixed
         select case (what)
         case ('INITEM')
            temp = value
         case ('TFIX')
            dtacc = dtacc + (value - temp)
            if (value /= temp) any_stress = .true.
            temp = value
            fixed = .true.
         case ('TFREE')
            fixed = .false.
         end select
      end subroutine set_one
   end subroutine do_temperature

   !> The thermal point nearest to (x, y): a gridpoint (kind 0), a corner of a
   !> block without zones (kind 1) or the centroid of one (kind 2); its id and
   !> position.
   subroutine nearest_thermal_point(model, x, y, kind, id, px, py)
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: x, y
      integer(ip), intent(out) :: kind, id
      real(wp), intent(out) :: px, py
      integer(ip) :: g, c, b
      real(wp) :: dist
      kind = 0
      id = 0
      px = 0.0_wp
      py = 0.0_wp
      dist = huge(1.0_wp)
      if (model%geometry%gridpoints%n > 0) then
         call nearest_gridpoint(model%geometry, x, y, g, dist)
         if (g > 0) then
            id = g
            px = model%geometry%gridpoints%x(g); py = model%geometry%gridpoints%y(g)
         else
            dist = huge(1.0_wp)
         end if
      end if
      associate (co => model%geometry%corners, bl => model%geometry%blocks)
         do c = 1, co%n
            if (rigid_corner(model, c)) call consider(1_ip, c, co%x(c), co%y(c))
         end do
         do b = 1, bl%n
            if (unzoned_block(model%geometry, b)) call consider(2_ip, b, bl%xc(b), bl%yc(b))
         end do
      end associate
   contains
      !> Point i of kind k at (xi, yi) replaces the nearest so far if closer.
      subroutine consider(k, i, xi, yi)
         integer(ip), intent(in) :: k, i
         real(wp), intent(in) :: xi, yi
         real(wp) :: d
         d = hypot(xi - x, yi - y)
         if (d < dist) then
            dist = d; kind = k; id = i; px = xi; py = yi
         end if
      end subroutine consider
   end subroutine nearest_thermal_point

   pure function point_kind_name(kind) result(name)
      integer(ip), intent(in) :: kind
      character(len=:), allocatable :: name
      select case (kind)
      case (1)
         name = 'corner'
      case (2)
         name = 'the centroid of block'
      case default
         name = 'gridpoint'
      end select
   end function point_kind_name

   !> THAPP range CONV h t | RAD h t | FLUX s c | SOURCE s c. Edge conditions
   !> go to every corner in the range (they act along an edge whose two corners
   !> both got them), SOURCE to every block whose centroid is in the range.
   subroutine do_thapp(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer :: kw
      integer(ip) :: kind, n
      real(wp) :: p1, p2
      associate (model => ctx%model, out => ctx%out)
         if (parsed%count_of([character(len=10) :: 'CONVECTION', 'FLUX', 'RADIATION', &
                              'SOURCE'], kw) /= 1) then
            call set_error(error, 'THAPP: expected one of CONVECTION h t, FLUX s c, ' &
                           //'RADIATION h t, SOURCE s c')
            return
         end if
         call require_block(model, 'THAPP', error)
         if (allocated(error)) return
         select case (parsed%items(kw)%name)
         case ('CONVECTION'); kind = bc_convection
         case ('FLUX'); kind = bc_flux
         case ('RADIATION'); kind = bc_radiation
         case default; kind = bc_source
         end select
         p1 = parsed%real_at(kw, 1)
         p2 = parsed%real_at(kw, 2)
         call ensure_thermal(model)
         model%thermal%nset = model%thermal%nset + 1
         n = 0
         if (kind == bc_source) then
            associate (bl => model%geometry%blocks)
               call add_records(bl%n, bl%live, bl%xc, bl%yc)
            end associate
            call out%line('THAPP SOURCE: '//itoa(n)//' block(s)')
         else
            associate (co => model%geometry%corners)
               call add_records(co%n, co%live, co%x, co%y)
            end associate
            call out%line('THAPP '//parsed%items(kw)%name//': '//itoa(n)//' corner(s)')
         end if
      end associate
   contains
      !> A record of the condition for each of the m entities (blocks or
      !> corners) that is live and whose point lies in the range.
      subroutine add_records(m, live, x, y)
         integer(ip), intent(in) :: m
         logical(l1), intent(in) :: live(:)
         real(wp), intent(in) :: x(:), y(:)
         integer(ip) :: i
         do i = 1, m
            if (.not. live(i)) cycle
            if (.not. parsed%range%contains_point(x(i), y(i))) cycle
            call thermal_add_record(ctx%model%thermal, kind, i, p1, p2, ctx%model%thermal%nset)
            n = n + 1
         end do
      end subroutine add_records
   end subroutine do_thapp

   !> RUN <AGE a> <DELT dt> <NOAGE> <TEMP t> <STEP n> <IMPLICIT> <TOL t> <CLOCK c>:
   !> limits are kept for later RUN commands (CLOCK is accepted and ignored);
   !> its mechanical hand-overs are timed for PRINT CYCLE.
   subroutine run_run(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer :: k
      logical :: implicit
      if (.not. allocated(ctx%model%thermal)) then
         call set_error(error, 'RUN: the model has no thermal part; give THERMAL first')
         return
      end if
      call ensure_thermal(ctx%model)
      implicit = .false.
      associate (th => ctx%model%thermal)
         do k = 1, parsed%nitems
            call parsed%take(k, 'AGE', th%age)
            call parsed%take(k, 'DELT', th%dt_user)
            call parsed%take(k, 'TEMP', th%temp_limit)
            call parsed%take(k, 'STEP', th%step_limit)
            call parsed%take(k, 'TOL', th%tol)
            if (parsed%items(k)%name == 'AGE') th%age_test = .true.
            if (parsed%items(k)%name == 'NOAGE') th%age_test = .false.
            if (parsed%items(k)%name == 'IMPLICIT') implicit = .true.
         end do
      end associate
      call thermal_run(ctx%model, implicit, ctx%out, error, ctx%cycle)
   end subroutine run_run

   !> THIST TEMPERATURE x y (nearest gridpoint) ... / NTCYC n / TYPE n / LIST /
   !> WRITE n file: everything is checked before anything changes.
   subroutine do_thist(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer :: k, nnew, n
      integer(ip) :: g, kind
      real(wp) :: px, py
      character(len=160) :: line
      associate (model => ctx%model, out => ctx%out)
         nnew = parsed%count_of(['TEMPERATURE'])
         n = 0
         if (allocated(model%thermal)) n = model%thermal%nthis
         if (n + nnew > max_thist) then
            call set_error(error, 'THIST TEMPERATURE: at most 20 thermal histories (RESET ' // &
                                  'THIST '// &
                           'clears the samples, not the points)')
            return
         end if
         if (nnew > 0 .and. model%geometry%blocks%n == 0) then
            call set_error(error, 'THIST TEMPERATURE: the model has no blocks')
            return
         end if
         do k = 1, parsed%nitems
            select case (parsed%items(k)%name)
            case ('TYPE', 'WRITE')
               if (parsed%int_at(k, 1) > n + nnew) then
                  call set_error(error, 'THIST '//parsed%items(k)%name//' '// &
                                 itoa(parsed%int_at(k, 1))//': no such thermal history (there ' // &
                                 'are ' &
                                 //itoa(n + nnew)//')')
                  return
               end if
            end select
         end do
         call ensure_thermal(model)
         associate (th => model%thermal)
            if (.not. allocated(th%this_gp)) then
               allocate (th%this_gp(max_thist), th%this_x(max_thist), th%this_y(max_thist))
               th%this_gp = 0
               th%this_x = 0.0_wp
               th%this_y = 0.0_wp
            end if
            if (.not. allocated(th%this_kind)) then
               allocate (th%this_kind(max_thist))
               th%this_kind = 0
            end if
            if (size(th%this_kind) < max_thist) then
               deallocate (th%this_kind)
               allocate (th%this_kind(max_thist))
               th%this_kind = 0
            end if
            do k = 1, parsed%nitems
               select case (parsed%items(k)%name)
               case ('TEMPERATURE')
                  call nearest_thermal_point(model, parsed%real_at(k, 1), parsed%real_at(k, 2), &
                                             kind, g, px, py)
                  th%nthis = th%nthis + 1
                  th%this_gp(th%nthis) = g
                  th%this_kind(th%nthis) = kind
                  th%this_x(th%nthis) = parsed%real_at(k, 1)
                  th%this_y(th%nthis) = parsed%real_at(k, 2)
                  write (line, '(a,i0,6a,1x,i0,5a)') 'thermal history ', th%nthis, &
                     ': temperature (', trim(format_real(th%this_x(th%nthis))), ',', &
                     trim(format_real(th%this_y(th%nthis))), ') taken at ', &
                     trim(point_kind_name(kind)), g, ' (', trim(format_real(px)), ',', &
                     trim(format_real(py)), ')'
                  call out%line(trim(line))
               case ('NTCYC')
                  th%ntcyc = parsed%int_at(k, 1)
               case ('TYPE')
                  th%this_type = parsed%int_at(k, 1)
               case ('LIST')
                  call print_thermal_histories(model, [integer ::], out)
               case ('WRITE')
                  call write_thermal_history(th, parsed%int_at(k, 1), parsed%text_at(k, 2), error)
                  if (allocated(error)) return
                  call out%line('THIST WRITE: history '//itoa(parsed%int_at(k, 1))// &
                                ' written to '//parsed%text_at(k, 2))
               end select
            end do
         end associate
      end associate
   end subroutine do_thist

   !> THIST WRITE n file: '#' header lines, then `time value` rows.
   subroutine write_thermal_history(th, h, file, error)
      type(thermal_t), intent(in) :: th
      integer, intent(in) :: h
      character(len=*), intent(in) :: file
      type(error_t), allocatable, intent(out) :: error
      integer :: unit, ios
      integer(ip) :: s
      logical :: ok
      call check_output_file('THIST WRITE', file, error)
      if (allocated(error)) return
      ! written beside the target and renamed into place, like HISTORY WRITE
      open (newunit=unit, file=temporary_name(file), status='replace', action='write', &
            iostat=ios)
      if (ios /= 0) then
         call set_error(error, 'THIST WRITE: cannot open '//file//' for writing')
         return
      end if
      write (unit, '(a,i0,a,i0)') '# udec thermal history ', h, ': temperature at gridpoint ', &
         th%this_gp(h)
      write (unit, '(a)') '# thermal time, temperature'
      do s = 1, th%nsamp
         write (unit, '(es22.14,1x,es22.14)') th%samp_time(s), &
            th%samp_val((s - 1)*max_thist + h)
      end do
      close (unit)
      call file_rename(temporary_name(file), file, ok)
      if (.not. ok) then
         call file_delete(temporary_name(file))
         call set_error(error, 'THIST WRITE: cannot write '//file)
      end if
   end subroutine write_thermal_history

   !> TABLE ntab x1 y1 x2 y2 ... (manual Section 4.5): table ntab (1 to 10,
   !> the range TADD accepts, Section 7.4.1) becomes the pairs given, x
   !> strictly increasing (TADD interpolates in x).
   subroutine do_table(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: v(:)
      integer :: k, j, n, ntab
      associate (model => ctx%model, out => ctx%out)
         ntab = int(parsed%int_at(1, 1))
         if (ntab < 1 .or. ntab > max_tables) then
            call set_error(error, 'TABLE: expected a table number from 1 to '//itoa(max_tables)// &
                           ', got '//parsed%text_at(1, 1))
            return
         end if
         allocate (v(0))
         do k = 2, parsed%nitems
            if (parsed%items(k)%keyword /= item_loose) cycle
            do j = 1, parsed%items(k)%count
               v = [v, parsed%real_at(k, j)]
            end do
         end do
         n = size(v)/2
         if (n < 1 .or. mod(size(v), 2) /= 0) then
            call set_error(error, 'TABLE '//itoa(ntab)//': expected pairs x y after the table ' &
                           //'number, got '//itoa(size(v))//' value(s)')
            return
         end if
         do j = 2, n
            if (v(2*j - 1) <= v(2*j - 3)) then
               call set_error(error, 'TABLE '//itoa(ntab)//': the x values must increase (pair '// &
                              itoa(j)//' has x = '//format_real(v(2*j - 1))//' after '// &
                              format_real(v(2*j - 3))//')')
               return
            end if
         end do
         call table_store(model%tables, ntab, v(1:2*n - 1:2), v(2:2*n:2))
         call out%line('TABLE '//itoa(ntab)//': '//itoa(n)//' pair(s)')
      end associate
   end subroutine do_table

   !> PRINT TABLE <ntab>: the pairs of table ntab, or of every table.
   subroutine print_tables(model, ids, out)
      type(model_t), intent(in) :: model
      integer, intent(in) :: ids(:)
      type(output_t), intent(in) :: out
      integer :: k, i, a, m
      character(len=80) :: line
      logical :: any_
      any_ = .false.
      do m = 1, merge(size(ids), max_tables, size(ids) > 0)
         k = m
         if (size(ids) > 0) k = ids(m)
         if (k < 1 .or. k > max_tables) then
            call out%line('*** PRINT TABLE: no table '//itoa(k)//' (tables 1 to '// &
                          itoa(max_tables)//')')
            cycle
         end if
         if (model%tables%len(k) == 0) then
            if (size(ids) > 0) call out%line('  table '//itoa(k)//': not defined (TABLE)')
            cycle
         end if
         any_ = .true.
         call out%line('  table '//itoa(k)//': '//itoa(model%tables%len(k))//' pair(s)')
         call out%line('             X             Y')
         a = sum(model%tables%len(1:k - 1))
         do i = a + 1, a + model%tables%len(k)
            write (line, '(2a14)') format_real(model%tables%x(i)), format_real(model%tables%y(i))
            call out%line(trim(line))
         end do
      end do
      if (size(ids) == 0 .and. .not. any_) call out%line('  no tables (TABLE ntab x y ...)')
   end subroutine print_tables

   !> TADD ntab xc yc ang1 ang2 (manual Section 7.4.1): the temperature of
   !> every gridpoint in the arc from ang1 anticlockwise to ang2 (degrees,
   !> -180 to 180; equal angles: the whole circle) around (xc, yc) rises by
   !> table ntab at its distance r from (xc, yc) (linear between the table's
   !> radii, its end values beyond them). TFIXed gridpoints keep their
   !> value. The changes induce thermal stress (Eq. 7-3), as the manual says.
   subroutine do_tadd(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer :: ntab
      integer(ip) :: g, n, nfix
      real(wp) :: xc, yc, a1, a2, ang, r, span, rel, dt
      logical :: any_stress
      associate (model => ctx%model, out => ctx%out)
         ntab = int(parsed%int_at(1, 1))
         xc = parsed%real_at(1, 2)
         yc = parsed%real_at(1, 3)
         a1 = parsed%real_at(1, 4)
         a2 = parsed%real_at(1, 5)
         if (ntab < 1 .or. ntab > max_tables) then
            call set_error(error, 'TADD: expected a table number from 1 to '//itoa(max_tables)// &
                           ', got '//parsed%text_at(1, 1))
            return
         end if
         if (model%tables%len(ntab) == 0) then
            call set_error(error, 'TADD: table '//itoa(ntab)//' is not defined (give TABLE '// &
                           itoa(ntab)//' r1 dT1 r2 dT2 ... first)')
            return
         end if
         if (abs(a1) > 180.0_wp .or. abs(a2) > 180.0_wp) then
            call set_error(error, 'TADD: the angles ang1 ang2 must lie between -180 and 180 ' &
                           //'degrees, got '//format_real(a1)//' '//format_real(a2))
            return
         end if
         if (model%geometry%blocks%n == 0) then
            call set_error(error, 'TADD: the model has no blocks')
            return
         end if
         call ensure_thermal(model)
         span = modulo(a2 - a1, 360.0_wp)
         if (span == 0.0_wp) span = 360.0_wp
         n = 0
         nfix = 0
         any_stress = .false.
         associate (gp => model%geometry%gridpoints, th => model%thermal, &
                    co => model%geometry%corners, bl => model%geometry%blocks)
            do g = 1, gp%n
               if (.not. gp%live(g)) cycle
               call add_one(gp%x(g), gp%y(g), th%temp(g), th%fixed(g), th%dtacc(g))
            end do
            ! corners and centroids of blocks without zones (Fig. 7-4)
            do g = 1, co%n
               if (.not. rigid_corner(model, g)) cycle
               call add_one(co%x(g), co%y(g), th%ctemp(g), th%cfixed(g), th%cdtacc(g))
            end do
            do g = 1, bl%n
               if (.not. unzoned_block(model%geometry, g)) cycle
               call add_one(bl%xc(g), bl%yc(g), th%btemp(g), th%bfixed(g), th%bdtacc(g))
            end do
         end associate
         if (any_stress) call thermal_apply_stress(model)
         if (nfix > 0) then
            call out%line('TADD: '//itoa(n)//' point(s) changed, '//itoa(nfix)// &
                          ' fixed (TFIX) kept')
         else
            call out%line('TADD: '//itoa(n)//' point(s) changed')
         end if

      end associate
   contains

      subroutine add_one(x, y, temp, fixed, dtacc)
         real(wp), intent(in) :: x, y
         real(wp), intent(inout) :: temp, dtacc
         logical, intent(in) :: fixed
         r = hypot(x - xc, y - yc)
         if (r > 0.0_wp .and. span < 360.0_wp) then
            ang = atan2(y - yc, x - xc)*180.0_wp/acos(-1.0_wp)
            rel = modulo(ang - a1, 360.0_wp)
            if (rel > span*(1.0_wp + 1.0e-12_wp)) return
         end if
         if (fixed) then
            nfix = nfix + 1
            return
         end if
         dt = table_value(ctx%model%tables, ntab, r)
         temp = temp + dt
         dtacc = dtacc + dt
         if (dt /= 0.0_wp) any_stress = .true.
         n = n + 1
      end subroutine add_one
   end subroutine do_tadd

   !> PRINT THIST n1 n2 ..: the samples; without numbers the list of points.
   subroutine print_thermal_histories(model, ids, out)
      type(model_t), intent(in) :: model
      integer, intent(in) :: ids(:)
      type(output_t), intent(in) :: out
      integer(ip) :: h, s
      integer :: j
      character(len=400) :: line
      if (.not. allocated(model%thermal)) then
         call out%line('*** PRINT THIST: the model has no thermal part (give THERMAL)')
         return
      end if
      associate (th => model%thermal)
         if (size(ids) == 0) then
            call out%line('  THIST  GRIDPT             X             Y')
            do h = 1, th%nthis
               write (line, '(2i8,2a14)') h, th%this_gp(h), format_real(th%this_x(h)), &
                  format_real(th%this_y(h))
               if (allocated(th%this_kind)) then
                  if (th%this_kind(h) == 1) line = trim(line)//'  (corner)'
                  if (th%this_kind(h) == 2) line = trim(line)//'  (block centroid)'
               end if
               call out%line(trim(line))
            end do
            if (th%nthis == 0) call out%line('  (no thermal histories)')
            return
         end if
         line = '          TIME'
         do j = 1, size(ids)
            if (ids(j) < 1 .or. ids(j) > th%nthis) then
               call out%line('*** PRINT THIST: no thermal history '//itoa(ids(j)))
               return
            end if
            write (line(len_trim(line) + 1:), '(i9,a5)') ids(j), ' TEMP'
         end do
         call out%line(trim(line))
         do s = 1, th%nsamp
            write (line, '(a14)') format_real(th%samp_time(s))
            do j = 1, size(ids)
               write (line(len_trim(line) + 1:), '(a14)') &
                  format_real(th%samp_val((s - 1)*max_thist + ids(j)))
            end do
            call out%line(trim(line))
         end do
      end associate
   end subroutine print_thermal_histories

   !> SET THDT dt / NTHER n / NMECH n.
   subroutine set_thermal_keyword(model, parsed, k)
      type(model_t), intent(inout) :: model
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k
      call ensure_thermal(model)
      call parsed%take(k, 'THDT', model%thermal%dt_user)
      call parsed%take(k, 'NTHER', model%thermal%nther)
      call parsed%take(k, 'NMECH', model%thermal%nmech)
   end subroutine set_thermal_keyword

   !> PRINT TEMPERATURE (PRINT GRIDPOINT TEMPERATURE): gridpoint, block, x, y,
   !> temperature, fixed flag; only gridpoints in the range when one is given.
   subroutine print_temperatures(model, parsed, out)
      type(model_t), intent(in) :: model
      type(parsed_t), intent(in) :: parsed
      type(output_t), intent(in) :: out
      integer(ip) :: g
      character(len=120) :: line
      if (.not. allocated(model%thermal)) then
         call out%line('*** PRINT TEMPERATURE: the model has no thermal part (give THERMAL)')
         return
      end if
      write (line, '(a)') '  GRIDPT   BLOCK             X             Y   TEMPERATURE  FIXED'
      call out%line(trim(line))
      associate (gp => model%geometry%gridpoints, th => model%thermal)
         do g = 1, min(gp%n, th%ng)
            if (gp%live(g)) call row(g, gp%x(g), gp%y(g), th%temp(g), th%fixed(g), gp%block(g))
         end do
      end associate
      ! blocks without zones: corners and centroids (Fig. 7-4)
      associate (co => model%geometry%corners, bl => model%geometry%blocks, &
                 th => model%thermal)
         if (th%nc == 0 .and. th%nb == 0) return
         if (.not. any([(unzoned_block(model%geometry, g), g=1, min(bl%n, th%nb))])) return
         call out%line('  CORNER   BLOCK             X             Y   TEMPERATURE  FIXED'// &
                       '   (blocks without zones)')
         do g = 1, min(co%n, th%nc)
            if (rigid_corner(model, g)) &
               call row(g, co%x(g), co%y(g), th%ctemp(g), th%cfixed(g), co%block(g))
         end do
         call out%line('           BLOCK             X             Y   TEMPERATURE  FIXED'// &
                       '   (centroids)')
         do g = 1, min(bl%n, th%nb)
            if (unzoned_block(model%geometry, g)) &
               call row(g, bl%xc(g), bl%yc(g), th%btemp(g), th%bfixed(g))
         end do
      end associate
   contains
      !> The row of a gridpoint, corner (with its block) or centroid (its id is
      !> the block's) at (x, y) when that point is in the range.
      subroutine row(id, x, y, temp, fixed, block)
         integer(ip), intent(in) :: id
         real(wp), intent(in) :: x, y, temp
         logical, intent(in) :: fixed
         integer(ip), intent(in), optional :: block
         if (.not. parsed%range%contains_point(x, y)) return
         if (present(block)) then
            write (line, '(2i8,3a14,a7)') id, block, format_real(x), format_real(y), &
               format_real(temp), merge('   yes', '      ', fixed)
         else
            write (line, '(8x,i8,3a14,a7)') id, format_real(x), format_real(y), &
               format_real(temp), merge('   yes', '      ', fixed)
         end if
         call out%line(trim(line))
      end subroutine row
   end subroutine print_temperatures

   !> PRINT BOUNDARY THERMAL (manual Section 4.5, PRINT BOUNDARY: "Thermal
   !> temperature at boundary"): the gridpoints on the free outer edges of
   !> the blocks, their temperature, TFIX and the THAPP conditions there.
   subroutine print_boundary_temperatures(model, out, range)
      type(model_t), intent(in) :: model
      type(output_t), intent(in) :: out
      type(range_t), intent(in), optional :: range
      type(block_grid_t) :: grid
      integer(ip) :: b, c, i, g, r, n
      logical :: fp, fn
      character(len=160) :: line
      character(len=40) :: conds
      character(len=4), parameter :: short(4) = ['CONV', 'FLUX', 'RAD ', 'SRC ']
      if (.not. allocated(model%thermal)) then
         call out%line('*** PRINT BOUNDARY THERMAL: the model has no thermal part (give THERMAL)')
         return
      end if
      if (.not. model%geometry%block_created) then
         call out%line('  no boundary: no BLOCK has been created')
         return
      end if
      call block_grid_build(model%geometry, grid)
      call out%line('Thermal boundary: temperature at the gridpoints of the free block edges')
      call out%line('  CORNER  GRIDPT   BLOCK             X             Y   TEMPERATURE  FIXED' // &
                    '  THAPP')
      n = 0
      associate (geo => model%geometry, th => model%thermal)
         do b = 1, geo%blocks%n
            if (.not. geo%blocks%live(b)) cycle
            c = geo%blocks%first_corner(b)
            do i = 1, geo%blocks%ncorner(b)
               g = geo%corners%gp(c)
               if (g > 0 .and. g <= th%ng) then
                  call corner_free_sides(geo, grid, c, fp, fn)
                  if (fp .or. fn) then
                     if (present(range)) then
                        if (.not. range%contains_point(geo%gridpoints%x(g), &
                                                       geo%gridpoints%y(g))) then
                           c = geo%corners%next(c)
                           cycle
                        end if
                     end if
                     conds = ''
                     do r = 1, th%nrec
                        if (th%rec_kind(r) /= bc_source .and. th%rec_id(r) == c) &
                           conds = trim(conds)//' '//short(th%rec_kind(r))
                     end do
                     write (line, '(3i8,3a14,a7,a)') c, g, b, format_real(geo%gridpoints%x(g)), &
                        format_real(geo%gridpoints%y(g)), format_real(th%temp(g)), &
                        merge('   yes', '      ', th%fixed(g)), '  '//trim(conds)
                     call out%line(trim(line))
                     n = n + 1
                  end if
               end if
               c = geo%corners%next(c)
            end do
         end do
      end associate
      if (n == 0) call out%line('  no boundary gridpoints (temperatures live on the zones of ' // &
                                'fully-deformable blocks: GENERATE)')
   end subroutine print_boundary_temperatures

   !> PRINT THERMAL: the RUN settings and the THAPP conditions.
   subroutine print_thermal_conditions(model, out)
      type(model_t), intent(in) :: model
      type(output_t), intent(in) :: out
      integer(ip) :: r
      character(len=160) :: line
      character(len=10), parameter :: names(4) = [character(len=10) :: 'CONVECTION', 'FLUX', &
                                                    'RADIATION', 'SOURCE']
      if (.not. allocated(model%thermal)) then
         call out%line('*** PRINT THERMAL: the model has no thermal part (give THERMAL)')
         return
      end if
      associate (th => model%thermal)
         write (line, '(a,es12.5,a,i0,a,es12.5)') 'Thermal time ', th%time, ', steps ', &
            th%nsteps, ', last time step ', th%dt_last
         call out%line(trim(line))
         write (line, '(a,es12.5,a,i0,a,es12.5,a,es12.5,a,i0,a,i0)') 'RUN limits: DELT ', &
            th%dt_user, ', STEP ', th%step_limit, ', TEMP ', th%temp_limit, ', TOL ', th%tol, &
            ', NTHER ', th%nther, ', NMECH ', th%nmech
         call out%line(trim(line))
         if (th%age_test) call out%line('AGE limit '//format_real(th%age))
         call out%line('   KIND        CORNER/BLOCK   PARAMETER 1   PARAMETER 2     TIME SET')
         do r = 1, th%nrec
            write (line, '(3x,a10,i14,3a14)') names(th%rec_kind(r)), th%rec_id(r), &
               format_real(th%rec_p1(r)), format_real(th%rec_p2(r)), format_real(th%rec_t0(r))
            call out%line(trim(line))
         end do
         if (th%nrec == 0) call out%line('   (no THAPP conditions: all boundaries adiabatic)')
      end associate
   end subroutine print_thermal_conditions

   !> THERMAL: heat conduction joins the model.
   subroutine run_thermal(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      call cannot_fail(error, parsed)
      call ensure_thermal(ctx%model)
      call ctx%out%line('THERMAL: heat conduction is part of the model (RUN takes thermal steps)')
   end subroutine run_thermal

end module commands_thermal
