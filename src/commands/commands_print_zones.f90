!> PRINT tables of fully-deformable blocks (manual Section 4.5): GRIDPOINT
!> DISP/FORCE/STATE, ZONE STATE/STRESS, the zone lines of PRINT MAX and
!> PRINT STRESS xl xu yl yu nx ny (principal stresses on a grid of points,
!> also written to the file STRESS). Column layouts: docs/print.md.
module commands_print_zones
   use commands_thermal, only: print_temperatures
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use core_output, only: output_t, fmt_real
   use core_range, only: range_t, in_range
   use core_files, only: file_rename, file_delete, temporary_name, check_output_file
   use model_state, only: model_t
   use model_zones, only: zone_elastic, zone_at_failure, zone_failed_past, zone_tension, &
                          vfix_x, vfix_y
   use model_zone_fields, only: zone_area, zone_centroid, zone_mass, principal_stresses, &
                                zone_at_point, any_zones
   use commands_parser, only: parsed_t
   use commands_numbers, only: format_real
   implicit none
   private
   public :: print_zone_keyword, print_zone_max, print_stress_grid, stress_grid_check
   public :: max_count_line, max_value_line
   public :: plasticity_text, stress_file_name

   !> The file PRINT STRESS writes besides the screen (manual: "STRESS").
   character(len=*), parameter :: stress_file_name = 'STRESS'
   !> PRINT STRESS refuses grids of more points (nx * ny) than this
   real(wp), parameter :: max_stress_points = 1.0e6_wp

contains

   !> Word for a plasticity indicator (PRINT ZONE STRESS).
   pure function plasticity_text(state) result(text)
      integer, intent(in) :: state
      character(len=:), allocatable :: text
      select case (state)
      case (zone_elastic)
         text = 'elastic'
      case (zone_at_failure)
         text = 'at-failure'
      case (zone_failed_past)
         text = 'failed-past'
      case (zone_tension)
         text = 'tension'
      case default
         text = '?'
      end select
   end function plasticity_text

   !> PRINT GRIDPOINT <DISP FORCE STATE TEMP> or PRINT ZONE <STATE STRESS>:
   !> item k of `parsed` with its `nsub` sub-keywords (none: every table).
   subroutine print_zone_keyword(model, parsed, k, nsub, material, out)
      type(model_t), intent(in) :: model
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k, nsub
      integer(ip), intent(in) :: material
      type(output_t), intent(in) :: out
      character(len=16), allocatable :: subs(:)
      integer :: j
      allocate (subs(nsub))
      do j = 1, nsub
         subs(j) = parsed%items(k + j)%name
      end do
      if (.not. any_zones(model%geometry)) then
         call out%line('  no zones: FDEF blocks have not been zoned (GENERATE)')
         return
      end if
      if (parsed%items(k)%name == 'ZONES') then
         if (nsub == 0) subs = [character(len=16) :: 'STATE', 'STRESS']
         do j = 1, size(subs)
            call zone_table(trim(subs(j)))
         end do
      else
         if (nsub == 0) subs = [character(len=16) :: 'DISPLACEMENTS', 'FORCES', 'STATE']
         do j = 1, size(subs)
            if (subs(j) == 'TEMPERATURE') then
               call print_temperatures(model, parsed, out)
            else
               call gridpoint_table(trim(subs(j)))
            end if
         end do
      end if
   contains
      !> An entity of block b at (x, y) is printed: it lies in the range (an
      !> unset range holds every point) and, when material > 0, its block is
      !> of that material.
      logical function shown(b, x, y)
         integer(ip), intent(in) :: b
         real(wp), intent(in) :: x, y
         shown = parsed%range%contains_point(x, y)
         if (material > 0) shown = shown .and. model%geometry%blocks%material(b) == material
      end function shown

      !> One gridpoint table; a gridpoint is in the range when its position is.
      subroutine gridpoint_table(which)
         character(len=*), intent(in) :: which
         integer(ip) :: g
         character(len=140) :: text
         character(len=2) :: fix
         select case (which)
         case ('DISPLACEMENTS')
            call out%line('  GRIDPT   BLOCK             X             Y        X-DISP        Y-DISP' &
                          //'         X-VEL         Y-VEL')
         case ('FORCES')
            call out%line('  GRIDPT   BLOCK             X             Y       X-FORCE       Y-FORCE')
         case default
            call out%line('  GRIDPT   BLOCK  CORNER             X             Y          MASS FIX  ADDRESS')
         end select
         associate (gp => model%geometry%gridpoints)
            do g = 1, gp%n
               if (.not. gp%live(g)) cycle
               if (.not. shown(gp%block(g), gp%x(g), gp%y(g))) cycle
               select case (which)
               case ('DISPLACEMENTS')
                  write (text, '(2i8,6a)') g, gp%block(g), fmt_real(gp%x(g)), fmt_real(gp%y(g)), &
                     fmt_real(gp%ux(g)), fmt_real(gp%uy(g)), fmt_real(gp%vx(g)), fmt_real(gp%vy(g))
               case ('FORCES')
                  write (text, '(2i8,4a)') g, gp%block(g), fmt_real(gp%x(g)), fmt_real(gp%y(g)), &
                     fmt_real(gp%fx(g)), fmt_real(gp%fy(g))
               case default
                  fix = merge('X', '-', iand(gp%vfix(g), vfix_x) /= 0)// &
                        merge('Y', '-', iand(gp%vfix(g), vfix_y) /= 0)
                  write (text, '(3i8,3a,2x,a2,i9)') g, gp%block(g), gp%corner(g), fmt_real(gp%x(g)), &
                     fmt_real(gp%y(g)), fmt_real(gp%mass(g)), fix, gp%addr(g)
               end select
               call out%line(trim(text))
            end do
         end associate
      end subroutine gridpoint_table

      !> One zone table; a zone is in the range when its centroid is.
      subroutine zone_table(which)
         character(len=*), intent(in) :: which
         integer(ip) :: z
         real(wp) :: xc, yc, smin, smax, angle
         character(len=160) :: text
         if (which == 'STATE') then
            call out%line('    ZONE   BLOCK     GP1     GP2     GP3          AREA          MASS  ADDRESS')
         else
            call out%line('    ZONE   BLOCK           SXX           SXY           SYY           SZZ' &
                          //'          SMIN          SMAX   ANGLE PLASTICITY')
         end if
         associate (geo => model%geometry, zn => model%geometry%zones)
            do z = 1, zn%n
               if (.not. zn%live(z)) cycle
               call zone_centroid(geo, z, xc, yc)
               if (.not. shown(zn%block(z), xc, yc)) cycle
               if (which == 'STATE') then
                  write (text, '(5i8,2a,i9)') z, zn%block(z), zn%g1(z), zn%g2(z), zn%g3(z), &
                     fmt_real(zone_area(geo, z)), fmt_real(zone_mass(geo, model%materials, z)), &
                     zn%addr(z)
               else
                  call principal_stresses(zn%sxx(z), zn%syy(z), zn%sxy(z), smin, smax, angle)
                  write (text, '(2i8,6a,f8.1,i4,1x,a)') z, zn%block(z), fmt_real(zn%sxx(z)), &
                     fmt_real(zn%sxy(z)), fmt_real(zn%syy(z)), fmt_real(zn%szz(z)), fmt_real(smin), &
                     fmt_real(smax), angle, zn%state(z), &
                     plasticity_text(zn%state(z))
               end if
               call out%line(trim(text))
            end do
         end associate
      end subroutine zone_table
   end subroutine print_zone_keyword

   !> The zone part of PRINT MAX (nothing when no zone is in the range, as
   !> the manual says: no zone data before the FDEF blocks are zoned).
   subroutine print_zone_max(model, out, range)
      type(model_t), intent(in) :: model
      type(output_t), intent(in) :: out
      type(range_t), intent(in), optional :: range
      integer(ip) :: z, g, nz, ng
      integer(ip) :: id(16)
      real(wp) :: v(16), m, xc, yc, smin, smax, angle, zsum, gsum, s(3), d
      integer :: k
      nz = 0
      ng = 0
      zsum = 0.0_wp
      gsum = 0.0_wp
      id = 0
      ! 1,2 zone mass min/max; 3,4 gp mass min/max; 5 min smin; 6 max smax;
      ! 7..12 min/max sxx syy sxy; 14 max gp velocity; 16 max gp displacement
      ! (odd slots keep minima, even slots maxima: keep)
      v(1:15:2) = huge(1.0_wp)
      v(2:16:2) = -huge(1.0_wp)
      associate (geo => model%geometry, zn => model%geometry%zones, &
                 gp => model%geometry%gridpoints)
         do z = 1, zn%n
            if (.not. zn%live(z)) cycle
            call zone_centroid(geo, z, xc, yc)
            if (.not. in_range(xc, yc, range)) cycle
            nz = nz + 1
            m = zone_mass(geo, model%materials, z)
            zsum = zsum + m
            call keep(1, m, z)
            call keep(2, m, z)
            call principal_stresses(zn%sxx(z), zn%syy(z), zn%sxy(z), smin, smax, angle)
            call keep(6, smax, z)
            call keep(5, smin, z)
            s = [zn%sxx(z), zn%syy(z), zn%sxy(z)]
            do k = 1, 3
               call keep(6 + 2*k, s(k), z)
               call keep(5 + 2*k, s(k), z)
            end do
         end do
         do g = 1, gp%n
            if (.not. gp%live(g)) cycle
            if (.not. in_range(gp%x(g), gp%y(g), range)) cycle
            ng = ng + 1
            gsum = gsum + gp%mass(g)
            call keep(3, gp%mass(g), g)
            call keep(4, gp%mass(g), g)
            d = hypot(gp%vx(g), gp%vy(g))
            call keep(14, d, g)
            d = hypot(gp%ux(g), gp%uy(g))
            call keep(16, d, g)
         end do
      end associate
      if (nz == 0 .and. ng == 0) return
      call max_count_line(out, 'number of zones', nz)
      call max_count_line(out, 'number of gridpoints', ng)
      if (nz > 0) then
         call mass_lines('zone', 'zone', 1, zsum, nz)
         call max_value_line(out, 'max principal stress (SMAX)', v(6), 'zone', id(6))
         call max_value_line(out, 'min principal stress (SMIN)', v(5), 'zone', id(5))
         call max_value_line(out, 'max SXX', v(8), 'zone', id(8))
         call max_value_line(out, 'min SXX', v(7), 'zone', id(7))
         call max_value_line(out, 'max SYY', v(10), 'zone', id(10))
         call max_value_line(out, 'min SYY', v(9), 'zone', id(9))
         call max_value_line(out, 'max SXY', v(12), 'zone', id(12))
         call max_value_line(out, 'min SXY', v(11), 'zone', id(11))
      end if
      if (ng > 0) then
         call mass_lines('gridpoint', 'gridpt', 3, gsum, ng)
         call max_value_line(out, 'max gridpoint velocity', v(14), 'gridpt', id(14))
         call max_value_line(out, 'max gridpoint displacement', v(16), 'gridpt', id(16))
      end if
   contains
      !> Slot i keeps the smallest value when i is odd, the largest when it
      !> is even (the first id on a tie).
      subroutine keep(i, value, entity)
         integer, intent(in) :: i
         real(wp), intent(in) :: value
         integer(ip), intent(in) :: entity
         if (merge(value < v(i), value > v(i), mod(i, 2) == 1)) then
            v(i) = value
            id(i) = entity
         end if
      end subroutine keep

      !> The minimum, average and maximum mass of the n zones or gridpoints
      !> (`what`, labelled `entity`) whose masses sum to `total` (slots i, i + 1).
      subroutine mass_lines(what, entity, i, total, n)
         character(len=*), intent(in) :: what, entity
         integer, intent(in) :: i
         real(wp), intent(in) :: total
         integer(ip), intent(in) :: n
         call max_value_line(out, what//' mass, minimum', v(i), entity, id(i))
         call max_value_line(out, what//' mass, average', total/real(n, wp), '', 0_ip)
         call max_value_line(out, what//' mass, maximum', v(i + 1), entity, id(i + 1))
      end subroutine mass_lines
   end subroutine print_zone_max

   !> Check the values of PRINT STRESS xl xu yl yu nx ny (item k).
   subroutine stress_grid_check(parsed, k, error, command)
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k
      type(error_t), allocatable, intent(out) :: error
      character(len=*), intent(in), optional :: command   !< default 'PRINT STRESS'
      character(len=:), allocatable :: name
      name = 'PRINT STRESS'
      if (present(command)) name = command
      if (parsed%items(k)%count /= 6) then
         call set_error(error, name//': expected xl xu yl yu nx ny (the grid of ' &
                        //'points), or ZONE STRESS for the zone table')
         return
      end if
      if (parsed%real_at(k, 2) <= parsed%real_at(k, 1) .or. &
          parsed%real_at(k, 4) <= parsed%real_at(k, 3)) then
         call set_error(error, name//': expected xl < xu and yl < yu, got '// &
                        format_real(parsed%real_at(k, 1))//' '//format_real(parsed%real_at(k, 2)) &
                        //' '//format_real(parsed%real_at(k, 3))//' '// &
                        format_real(parsed%real_at(k, 4)))
         return
      end if
      ! a mistyped nx ny (100000 100000) would print 1e10 lines to the
      ! screen, OUT and the STRESS file
      if (real(parsed%int_at(k, 5), wp)*real(parsed%int_at(k, 6), wp) > max_stress_points) then
         call set_error(error, name//': nx ny = '//format_real(real(parsed%int_at(k, 5), wp)) &
                        //' '//format_real(real(parsed%int_at(k, 6), wp))//' would print more than ' &
                        //'1 000 000 points; give a coarser grid')
      end if
   end subroutine stress_grid_check

   !> PRINT STRESS xl xu yl yu nx ny: principal stresses at the centres of
   !> an nx by ny grid of cells covering the box (so every point is strictly
   !> inside it), row by row from the bottom, x fastest. Each point takes the
   !> stresses of the zone containing it; a point in no zone is listed as
   !> outside. The same lines go to the file `file` (written to a temporary
   !> and renamed into place).
   subroutine print_stress_grid(model, xl, xu, yl, yu, nx, ny, out, file, error)
      type(model_t), intent(in) :: model
      real(wp), intent(in) :: xl, xu, yl, yu
      integer, intent(in) :: nx, ny
      type(output_t), intent(in) :: out
      character(len=*), intent(in) :: file
      type(error_t), allocatable, intent(out) :: error
      integer :: i, j, u, ios
      integer(ip) :: z
      real(wp) :: x, y, smin, smax, angle
      character(len=160) :: text
      logical :: ok
      call check_output_file('PRINT STRESS', file, error)
      if (allocated(error)) return
      open (newunit=u, file=temporary_name(file), status='replace', action='write', iostat=ios)
      if (ios /= 0) then
         call set_error(error, "PRINT STRESS: cannot write the file '"//file//"'")
         return
      end if
      write (text, '(a,i0,a,i0,a)') '  principal stresses on ', nx, ' x ', ny, &
         ' points in '//format_real(xl)//' < x < '//format_real(xu)//', '// &
         format_real(yl)//' < y < '//format_real(yu)
      call put(text)
      call put('             X             Y          SMIN          SMAX   ANGLE    ZONE')
      do j = 1, ny
         y = yl + (real(j, wp) - 0.5_wp)*(yu - yl)/real(ny, wp)
         do i = 1, nx
            x = xl + (real(i, wp) - 0.5_wp)*(xu - xl)/real(nx, wp)
            z = zone_at_point(model%geometry, x, y)
            if (z > 0) then
               associate (zn => model%geometry%zones)
                  call principal_stresses(zn%sxx(z), zn%syy(z), zn%sxy(z), smin, smax, angle)
               end associate
               write (text, '(4a,f8.1,i8)') fmt_real(x), fmt_real(y), fmt_real(smin), &
                  fmt_real(smax), angle, z
            else
               write (text, '(3a)') fmt_real(x), fmt_real(y), '   outside (in no zone)'
            end if
            call put(text)
         end do
      end do
      close (u)
      call file_rename(temporary_name(file), file, ok)
      if (.not. ok) then
         call file_delete(temporary_name(file))
         call set_error(error, "PRINT STRESS: cannot write the file '"//file//"'")
         return
      end if
      call out%line('  (also written to the file '//file//')')
   contains
      subroutine put(line)
         character(len=*), intent(in) :: line
         call out%line(trim(line))
         write (u, '(a)') trim(line)
      end subroutine put
   end subroutine print_stress_grid

   !> A count line of PRINT MAX: label, integer.
   subroutine max_count_line(out, label, n)
      type(output_t), intent(in) :: out
      character(len=*), intent(in) :: label
      integer(ip), intent(in) :: n
      character(len=80) :: text
      character(len=28) :: l
      l = label
      write (text, '(2x,a28,i14)') l, n
      call out%line(text)
   end subroutine max_count_line

   !> A value line of PRINT MAX: label, value and, when id > 0, the entity
   !> kind and id where it occurs.
   subroutine max_value_line(out, label, v, entity, id)
      type(output_t), intent(in) :: out
      character(len=*), intent(in) :: label, entity
      real(wp), intent(in) :: v
      integer(ip), intent(in) :: id
      character(len=80) :: text
      character(len=28) :: l
      character(len=7) :: e
      l = label
      e = entity
      if (id > 0) then
         write (text, '(2x,a28,a,2x,a7,i8)') l, fmt_real(v), e, id
      else
         write (text, '(2x,a28,a)') l, fmt_real(v)
      end if
      call out%line(text)
   end subroutine max_value_line

end module commands_print_zones
