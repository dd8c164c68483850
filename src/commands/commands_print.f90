!> PRINT <range> keyword <keyword ...> (manual Section 4.5). The line is
!> checked as a whole first (misplaced sub-keywords, JOINT without its line,
!> geometry tables before any BLOCK), then each keyword prints in turn.
!> Sub-keywords attach to the keyword before them: CONTACT DISP/FORCE/STATE,
!> BOUNDARY BE/DISP/FLUID/FORCE/STATE/THERMAL, GRIDPOINT ..., PROPERTY <kind>.
!> FILE name sends the output of the keywords after it to that file (written
!> to a temporary and renamed into place when the line is done). Zones and
!> gridpoints (ZONE, GRIDPOINT, STRESS, the zone part of MAX) are printed by
!> commands_print_zones. Keywords for data this version does not have yet
!> (flow, thermal, structural elements, ...) print a 'not yet available'
!> line and the run goes on. Column layouts: docs/print.md.
module commands_print
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use core_output, only: output_t, fmt_real, itoa
   use core_range, only: range_t, in_range
   use core_files, only: file_rename, file_delete, temporary_name, check_output_file
   use model_state, only: model_t
   use model_fluid, only: fluid_t
   use model_thermal, only: thermal_t
   use model_geometry, only: geometry_t, geometry_live_blocks
   use model_history, only: history_t, hist_keyword, history_first, hist_ndis, hist_sdis, &
                            hist_nstr, hist_sstr, hist_srat, hist_bfx, hist_bfy, hist_bfm, &
                            hist_xvel, &
                            hist_yvel, hist_xdis, hist_ydis, hist_gxvel, hist_gyvel, hist_gxdis, &
                            hist_gydis, hist_sxx, hist_sxy, hist_syy
   use model_mechanics, only: damping_none, damping_auto, damping_rayleigh, damping_local
   use geometry_polygon, only: segment_distance
   use contact_refresh, only: geometry_refresh
   use contact_print, only: print_block_table, print_sdef, print_corners, &
                            print_contact_table, contact_table_names, print_domains, &
                            print_list, print_domain_list, contact_flags_text, domain_centre
   use commands_properties, only: print_properties
   use model_properties, only: prop_ares, prop_azero, prop_bulk, prop_ccohesion, prop_cdilation, &
                                prop_cfriction, prop_cohesion, prop_cperm, prop_ctensile, &
                                prop_density, prop_dilation, prop_friction, prop_hbm, prop_hbs, &
                                prop_jcoh, prop_jdil, prop_jen, prop_jes, prop_jfric, prop_jif, &
                                prop_jkn, prop_jks, prop_jperm, prop_jr, prop_jtensile, prop_kn, &
                                prop_ks, prop_raexp, prop_rastiff, prop_rlength, prop_rrfac, &
                                prop_rsexp, prop_rsstiff, prop_ruaxial, prop_rushear, &
                                prop_shear, prop_specheat, prop_tensile, prop_tf, prop_thexp, &
                                prop_ucs, prop_xcond, prop_ycomp, prop_ycond, prop_yield
   use commands_boundary, only: boundary_print, ffield_print
   use commands_print_zones, only: max_count_line, max_value_line, print_zone_keyword, print_zone_max, print_stress_grid, &
                                   stress_grid_check, stress_file_name
   use commands_be, only: be_print, be_print_bebound, be_print_beint
   use commands_structure, only: structure_print
   use commands_reinforce, only: reinforce_print
   use commands_fluid, only: print_flows, print_fluid_domains
   use commands_thermal, only: print_temperatures, print_thermal_conditions, &
                               print_thermal_histories, print_boundary_temperatures, &
                               print_tables
   use commands_parser, only: parsed_t
   use commands_context, only: context_t, registry_t
   use engine_stages, only: cycle_report_t, cycle_report_print
   use engine_rigid_velocity, only: rigid_velocity_t, rigid_velocity_present, rigid_velocity_build, &
                                    rigid_velocity_free_force
   use model_boundary, only: boundary_t
   use commands_numbers, only: format_real
   implicit none
   private
   public :: register_print_commands
   public :: handle_print, print_max, print_status, print_settings, print_history, print_history_max
   public :: print_joint

   !> A PRINT FILE destination being written.
   type :: print_file_t
      logical :: open = .false.
      integer :: unit = -1
      character(len=:), allocatable :: name
   end type print_file_t

contains

   !> The commands of this family in the registry (commands_context).
   subroutine register_print_commands(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('print', 'PRint', '[R]', '', 'MAt q;BEBound;BEInt qrrrr;Blocks;' // &
                   'BOundary {BE,Displacements,Fluid,Forces,State,Thermal};BE;DIsplacements;' // &
                   'FLUid;FOrces;STATE;THErmal;CAble;Contacts {Displacements,Forces,State};' // &
                   'CORners;CYcle;DList;Domains;File s;Flows;' // &
                   'Gridpoints {Displacements,Forces,State,Temperature};TEmperature;History q*;' // &
                   'HMax q*;Joint [rrrr[p]];List;LM;Maxima;' // &
                   'Property {Blocks,BOundary,CABle,Contacts,Fluid,Joint,Reinforcement,' // &
                   'Structural,Thermal};Reinforcement;STRUctural;RIgid;SDEF;STatus;STC;STE;' // &
                   'STRess [rrrrqq];Table q*;Zones {STate,STRess};THIst q*;FF', '4.5', &
                   'print model data (CYCLE: the stages of a step and their share of wall time)', &
                   run_print)
      call reg%add('print', 'STress', 'rrrrqq', '', '', '4.5', &
                   'principal stresses in a range printed on a grid (as PRINT STRESS)', &
                   handler=do_stress, unit='m', args='xl xu yl yu nx ny')
   end subroutine register_print_commands

   !> Execute one PRINT line.
   subroutine handle_print(model, parsed, out, error, cycle)
      type(model_t), intent(inout) :: model
      type(parsed_t), intent(in) :: parsed
      type(output_t), intent(in) :: out
      type(error_t), allocatable, intent(out) :: error
      !> stage timing of the last CYCLE (PRINT CYCLE)
      type(cycle_report_t), intent(in), optional :: cycle
      type(output_t) :: dest
      type(print_file_t) :: file
      type(error_t), allocatable :: close_error
      call walk(model, parsed, out, .false., dest, file, error, cycle)
      if (allocated(error)) return
      dest = out
      call walk(model, parsed, out, .true., dest, file, error, cycle)
      call finish_file(file, close_error)
      if (.not. allocated(error) .and. allocated(close_error)) call move_alloc(close_error, error)
   end subroutine handle_print

   !> Go through the keywords of the line: check only (`run` false) or print.
   subroutine walk(model, parsed, out, run, dest, file, error, cycle)
      type(model_t), intent(inout) :: model
      type(parsed_t), intent(in) :: parsed
      type(output_t), intent(in) :: out
      logical, intent(in) :: run
      type(output_t), intent(inout) :: dest
      type(print_file_t), intent(inout) :: file
      type(error_t), allocatable, intent(out) :: error
      type(cycle_report_t), intent(in), optional :: cycle
      type(cycle_report_t) :: no_cycle
      integer :: k, j, i, nsub, kmat
      integer(ip) :: material
      logical :: mat_used
      character(len=:), allocatable :: name
      if (.not. any(parsed%items(1:parsed%nitems)%keyword > 0)) then
         call set_error(error, 'PRINT: expected a keyword such as BLOCK, CONTACT, MAX, ' &
                        //'HIST or STATUS')
         return
      end if
      kmat = parsed%find('MAT')
      material = 0
      if (kmat > 0) material = parsed%int_at(kmat, 1)
      mat_used = .false.
      k = 1
      do while (k <= parsed%nitems)
         name = parsed%items(k)%name
         j = k + 1
         do while (j <= parsed%nitems)
            if (.not. is_sub_keyword(name, parsed, j)) exit
            j = j + 1
         end do
         nsub = j - k - 1
         select case (name)
         case ('', 'MAT')
         case ('FILE')
            ! manual 4.5: FILE must precede the keywords whose data go to the file
            if (.not. any([(parsed%items(i)%keyword > 0 .and. parsed%items(i)%name /= 'FILE' &
                            .and. parsed%items(i)%name /= 'MAT', i=k + 1, parsed%nitems)])) then
               call set_error(error, "PRINT FILE "//parsed%text_at(k, 1)//": FILE must " &
                              //"precede the keywords whose output goes to the file (e.g. " &
                              //"PRINT FILE "//parsed%text_at(k, 1)//" HIST 1); no keyword " &
                              //"follows it")
               return
            end if
            if (run) then
               call finish_file(file, error)
               if (allocated(error)) return
               call start_file(file, parsed%text_at(k, 1), dest, error)
               if (allocated(error)) return
            end if
         case ('DISPLACEMENTS', 'FORCES', 'STATE')
            call set_error(error, 'PRINT '//name//': give it after CONTACT, BOUNDARY or ' &
                           //'GRIDPOINT (e.g. PRINT CONTACT '//name//')')
            return
         case ('BLOCKS', 'RIGID', 'CORNERS', 'CONTACTS', 'DOMAINS', 'LIST', 'DLIST', 'SDEF')
            if (name == 'BLOCKS' .or. name == 'RIGID' .or. name == 'SDEF') mat_used = .true.
            ! an empty model prints as empty, as ZONE, HIST and BOUNDARY do: a
            ! PRINT changes nothing and must not end a batch run
            if (run .and. .not. model%geometry%block_created) &
               call dest%line('  PRINT '//name//': none (no BLOCK has been created)')
            if (run .and. model%geometry%block_created) &
               call print_geometry_table(model, parsed, name, k, nsub, material, dest)
         case ('JOINT')
            if (parsed%items(k)%count < 4) then
               call set_error(error, 'PRINT JOINT: expected x1 y1 x2 y2 <tolc> (the line ' &
                              //'along the joint)')
               return
            end if
            if (run .and. .not. model%geometry%block_created) &
               call dest%line('  PRINT JOINT: none (no BLOCK has been created)')
            if (run .and. model%geometry%block_created) call do_joint(model, parsed, k, dest)
         case ('ZONES', 'GRIDPOINTS')
            mat_used = .true.
            if (run) call print_zone_keyword(model, parsed, k, nsub, material, dest)
         case ('STRESS')
            call stress_grid_check(parsed, k, error)
            if (allocated(error)) return
            if (run) call print_stress_grid(model, parsed%real_at(k, 1), parsed%real_at(k, 2), &
                                            parsed%real_at(k, 3), parsed%real_at(k, 4), &
                                            parsed%int_at(k, 5), parsed%int_at(k, 6), dest, &
                                            stress_file_name, error)
            if (allocated(error)) return
         case ('MAXIMA')
            if (run) call do_max(model, parsed, dest)
         case ('CYCLE')
            if (run .and. present(cycle)) call cycle_report_print(cycle, model, dest)
            if (run .and. .not. present(cycle)) call cycle_report_print(no_cycle, model, dest)
         case ('STATUS')
            if (run .and. model%geometry%block_created) call geometry_refresh(model%geometry)
            if (run) call print_status(model, dest)
         case ('HISTORY')
            if (run) call print_history(model%hist, item_ints(parsed, k), dest)
         case ('HMAX')
            if (run) call print_history_max(model%hist, item_ints(parsed, k), dest)
         case ('PROPERTY')
            if (run) call do_property(model, parsed, k, nsub, dest)
         case ('BOUNDARY')
            if (run) call do_boundary_print(model, parsed, k, nsub, dest)
         case ('BE')
            if (run) call be_print(model, dest)
         case ('BEBOUND')
            if (run) call be_print_bebound(model, dest)
         case ('BEINT')
            ! n x1 y1 x2 y2 are all there (the grammar's qrrrr)
            if (parsed%int_at(k, 1) < 1 .or. parsed%int_at(k, 1) > 100000) then
               call set_error(error, 'PRINT BEINT: expected a number of points n from 1 to ' &
                              //'100000, got '//parsed%text_at(k, 1))
               return
            end if
            if (run) call be_print_beint(model, int(parsed%int_at(k, 1)), parsed%real_at(k, 2), &
                                         parsed%real_at(k, 3), parsed%real_at(k, 4), &
                                         parsed%real_at(k, 5), dest)
         case ('STE', 'STC', 'LM')
            if (run) call structure_print(model, name, dest)
         case ('STRUCTURAL')
            ! the manual lists Structural under PRINT PROPERTY; alone it
            ! prints the same table (structural element properties)
            if (run) then
               call dest%line('  STRUCTURAL properties')
               call print_properties(model, dest, kind_properties('STRUCTURAL'))
            end if
         case ('CABLE', 'REINFORCEMENT')
            if (run) call reinforce_print(model, name, dest)
         case ('TEMPERATURE')
            if (run) call print_temperatures(model, parsed, dest)
         case ('THERMAL')
            if (run) call print_thermal_conditions(model, dest)
         case ('THIST')
            if (run) call print_thermal_histories(model, item_ints(parsed, k), dest)
         case ('FF')
            if (run) call ffield_print(model, dest)
         case ('TABLE')
            if (run) call print_tables(model, item_ints(parsed, k), dest)
         case ('FLOWS', 'FLUID')
            if (run .and. allocated(model%fluid)) then
               if (name == 'FLOWS') call print_flows(model, dest)
               if (name == 'FLUID') call print_fluid_domains(model, dest)
            else if (run) then
               call dest%line('*** PRINT '//name//': not yet available ('//missing_data(name)//')')
            end if
         case default
            if (run) call dest%line('*** PRINT '//name//': not yet available ('// &
                                    missing_data(name)//')')
         end select
         k = j
      end do
      if (run .and. kmat > 0 .and. .not. mat_used) &
         call out%line('Note: PRINT MAT n selects blocks for BLOCK, RIGID, SDEF, ZONE and GRIDPOINT ' &
                       //'only; ignored')
   end subroutine walk

   !> Is item j a sub-keyword of keyword `main` (the item before the run)?
   logical function is_sub_keyword(main, parsed, j) result(sub)
      character(len=*), intent(in) :: main
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: j
      character(len=:), allocatable :: s
      s = parsed%items(j)%name
      select case (main)
      case ('CONTACTS')
         sub = any(s == [character(len=13) :: 'DISPLACEMENTS', 'FORCES', 'STATE'])
      case ('BOUNDARY')
         sub = any(s == [character(len=13) :: 'BE', 'DISPLACEMENTS', 'FLUID', 'FORCES', &
                         'STATE', 'THERMAL'])
      case ('GRIDPOINTS')
         sub = any(s == [character(len=13) :: 'DISPLACEMENTS', 'FORCES', 'STATE', &
                         'TEMPERATURE'])
      case ('ZONES')
         sub = s == 'STATE' .or. (s == 'STRESS' .and. parsed%items(j)%count == 0)
      case ('PROPERTY')
         sub = any(s == [character(len=13) :: 'BLOCKS', 'BOUNDARY', 'CABLE', 'CONTACTS', &
                         'FLUID', 'REINFORCEMENT', 'STRUCTURAL', 'THERMAL'])
         if (s == 'JOINT') sub = parsed%items(j)%count == 0
      case default
         sub = .false.
      end select
   end function is_sub_keyword

   !> Why a keyword has nothing to print yet.
   function missing_data(name) result(why)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: why
      select case (name)
      case ('FLOWS', 'FLUID')
         why = 'no fluid in the model: give FLUID first'
      case ('FF')
         why = 'free-field boundaries are not implemented yet'
      case default
         why = 'not implemented yet'
      end select
   end function missing_data

   !> The integer values of item k (HIST n.., HMAX n..).
   function item_ints(parsed, k) result(ids)
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k
      integer, allocatable :: ids(:)
      integer :: j
      allocate (ids(parsed%items(k)%count))
      do j = 1, size(ids)
         ids(j) = parsed%int_at(k, j)
      end do
   end function item_ints

   !> Open the temporary of PRINT FILE name and send `dest` there only.
   subroutine start_file(file, name, dest, error)
      type(print_file_t), intent(inout) :: file
      character(len=*), intent(in) :: name
      type(output_t), intent(inout) :: dest
      type(error_t), allocatable, intent(out) :: error
      integer :: ios
      call check_output_file('PRINT FILE', name, error)
      if (allocated(error)) return
      open (newunit=file%unit, file=temporary_name(name), status='replace', action='write', &
            iostat=ios)
      if (ios /= 0) then
         call set_error(error, "PRINT FILE: cannot open '"//name//"' for writing")
         return
      end if
      file%open = .true.
      file%name = name
      dest = output_t()
      dest%screen = .false.
      call dest%add_unit(file%unit)
   end subroutine start_file

   !> Close the PRINT FILE temporary and rename it into place.
   subroutine finish_file(file, error)
      type(print_file_t), intent(inout) :: file
      type(error_t), allocatable, intent(out) :: error
      logical :: ok
      if (.not. file%open) return
      close (file%unit)
      file%open = .false.
      call file_rename(temporary_name(file%name), file%name, ok)
      if (.not. ok) then
         call file_delete(temporary_name(file%name))
         call set_error(error, "PRINT FILE: cannot write '"//file%name//"'")
      end if
   end subroutine finish_file

   !> BLOCK, RIGID, CORNERS, CONTACT (+ DISP/FORCE/STATE), DOMAIN, LIST, DLIST.
   subroutine print_geometry_table(model, parsed, name, k, nsub, material, out)
      type(model_t), intent(inout) :: model
      type(parsed_t), intent(in) :: parsed
      character(len=*), intent(in) :: name
      integer, intent(in) :: k, nsub
      integer(ip), intent(in) :: material
      type(output_t), intent(in) :: out
      integer :: j
      call geometry_refresh(model%geometry)
      if (parsed%has_range) then
         call tables(parsed%range)
      else
         call tables()
      end if
   contains
      subroutine tables(range)
         type(range_t), intent(in), optional :: range
         select case (name)
         case ('BLOCKS')
            call print_block_table(model%geometry, out, 'BLOCKS', range, material)
            call print_sdef(model%geometry, out, range, material, quiet=.true.)
         case ('SDEF')
            call print_sdef(model%geometry, out, range, material)
         case ('RIGID')
            call print_block_table(model%geometry, out, 'RIGID', range, material)
         case ('CORNERS')
            call print_corners(model%geometry, out, range)
         case ('DOMAINS')
            call print_domains(model%geometry, out, range)
            if (allocated(model%fluid)) call print_fluid_domains(model, out, range)
         case ('LIST')
            call print_list(model%geometry, out, range)
         case ('DLIST')
            call print_domain_list(model%geometry, out)
         case ('CONTACTS')
            if (nsub == 0) then
               do j = 1, size(contact_table_names)
                  call print_contact_table(model%geometry, out, trim(contact_table_names(j)), range)
               end do
            end if
            do j = k + 1, k + nsub
               call print_contact_table(model%geometry, out, trim(parsed%items(j)%name), range)
            end do
         end select
      end subroutine tables
   end subroutine print_geometry_table

   !> PRINT BOUNDARY <STATE DISP FORCES ...>: commands_boundary (docs/print.md).
   !> PRINT BOUNDARY: the BOUNDARY conditions (commands_boundary), BE the
   !> boundary-element nodes (commands_be), THERMAL the temperatures at the
   !> boundary (commands_thermal); without a sub-keyword all of them.
   subroutine do_boundary_print(model, parsed, k, nsub, out)
      type(model_t), intent(inout) :: model
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k, nsub
      type(output_t), intent(inout) :: out
      character(len=16) :: subs(nsub)
      integer :: j, m
      logical :: be, thermal
      m = 0
      be = nsub == 0
      thermal = nsub == 0
      do j = 1, nsub
         select case (parsed%items(k + j)%name)
         case ('BE')
            be = .true.
         case ('THERMAL')
            thermal = .true.
         case default
            m = m + 1
            subs(m) = parsed%items(k + j)%name
         end select
      end do
      if (nsub == 0 .or. m > 0) then
         if (parsed%has_range) then
            call boundary_print(model, subs(1:m), out, parsed%range)
         else
            call boundary_print(model, subs(1:m), out)
         end if
      end if
      if (be) then
         if (model%be%ne > 0 .or. nsub > 0) call be_print(model, out)
      end if
      if (thermal) then
         if (allocated(model%thermal) .or. nsub > 0) then
            if (parsed%has_range) then
               call print_boundary_temperatures(model, out, parsed%range)
            else
               call print_boundary_temperatures(model, out)
            end if
         end if
      end if
   end subroutine do_boundary_print

   subroutine do_joint(model, parsed, k, out)
      type(model_t), intent(inout) :: model
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k
      type(output_t), intent(in) :: out
      real(wp) :: tolc
      ! manual: without tolc the band is twice the rounding length wide
      tolc = model%geometry%round
      if (parsed%items(k)%count >= 5) tolc = parsed%real_at(k, 5)
      call geometry_refresh(model%geometry)
      if (parsed%has_range) then
         call print_joint(model%geometry, out, parsed%real_at(k, 1), parsed%real_at(k, 2), &
                          parsed%real_at(k, 3), parsed%real_at(k, 4), tolc, parsed%range)
      else
         call print_joint(model%geometry, out, parsed%real_at(k, 1), parsed%real_at(k, 2), &
                          parsed%real_at(k, 3), parsed%real_at(k, 4), tolc)
      end if
   end subroutine do_joint

   !> PRINT JOINT x1,y1 x2,y2 tolc: contacts within tolc of the segment,
   !> ordered by their position along it, with forces and displacements.
   subroutine print_joint(geo, out, x1, y1, x2, y2, tolc, range)
      type(geometry_t), intent(in) :: geo
      type(output_t), intent(in) :: out
      real(wp), intent(in) :: x1, y1, x2, y2, tolc
      type(range_t), intent(in), optional :: range
      integer(ip), allocatable :: ids(:)
      real(wp), allocatable :: along(:), dist(:)
      integer(ip) :: c, n, i, m
      real(wp) :: d, t, seg, ta, da
      character(len=140) :: text
      allocate (ids(max(geo%contacts%n, 1)), along(max(geo%contacts%n, 1)), &
                dist(max(geo%contacts%n, 1)))
      seg = hypot(x2 - x1, y2 - y1)
      n = 0
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         if (present(range)) then
            if (.not. range%contains_point(geo%contacts%x(c), geo%contacts%y(c))) cycle
         end if
         call segment_distance(geo%contacts%x(c), geo%contacts%y(c), x1, y1, x2, y2, d, t)
         if (d > tolc) cycle
         ! insertion by position along the line
         i = n
         do while (i >= 1)
            if (along(i) <= t*seg) exit
            ids(i + 1) = ids(i)
            along(i + 1) = along(i)
            dist(i + 1) = dist(i)
            i = i - 1
         end do
         ids(i + 1) = c
         along(i + 1) = t*seg
         dist(i + 1) = d
         n = n + 1
      end do
      write (text, '(i0)') n
      call out%line('  joint ('//format_real(x1)//', '//format_real(y1)//') to ('// &
                    format_real(x2)//', '//format_real(y2)//'), band +/- '// &
                    format_real(tolc)//': '//trim(text)//' contact(s)')
      call out%line(' CONTACT  BLOCK1  BLOCK2         ALONG      DISTANCE        LENGTH' // &
                    '  NORMAL-FORCE   SHEAR-FORCE    SHEAR-DISP   NORMAL-DISP STATE')
      do m = 1, n
         c = ids(m)
         ta = along(m)
         da = dist(m)
         write (text, '(3i8,7a,3x,a3)') c, geo%contacts%block1(c), geo%contacts%block2(c), &
            fmt_real(ta), fmt_real(da), fmt_real(geo%contacts%length(c)), &
            fmt_real(geo%contacts%state%fn(c)), fmt_real(geo%contacts%state%fs(c)), &
            fmt_real(geo%contacts%state%us(c)), fmt_real(geo%contacts%state%un(c)), &
            contact_flags_text(geo%contacts%state%flags(c))
         call out%line(text)
      end do
   end subroutine print_joint

   subroutine do_max(model, parsed, out)
      type(model_t), intent(inout) :: model
      type(parsed_t), intent(in) :: parsed
      type(output_t), intent(in) :: out
      if (model%geometry%block_created) call geometry_refresh(model%geometry)
      if (parsed%has_range) then
         call print_max(model%geometry, model%bound, model%gravity, out, parsed%range)
         call print_zone_max(model, out, parsed%range)
      else
         call print_max(model%geometry, model%bound, model%gravity, out)
         call print_zone_max(model, out)
      end if
   end subroutine do_max

   !> PRINT MAX: counts, block mass range, largest block velocity,
   !> displacement and unbalanced force, contact force and displacement
   !> extremes, each with the id of the entity (blocks and contacts in range).
   subroutine print_max(geo, bnd, grav, out, range)
      type(geometry_t), intent(in) :: geo
      type(boundary_t), intent(in) :: bnd
      real(wp), intent(in) :: grav(2)
      type(output_t), intent(in) :: out
      type(range_t), intent(in), optional :: range
      integer(ip) :: b, c, d, nb, nc, ncor, nd, nrigid, nfree, j
      integer(ip) :: bmin, bmax, bvel, bdis, bfor, cfn, cfnmin, cfs, cus, cun
      real(wp) :: mmin, mmax, msum, vel, dis, for, fn, fnmin, fs, us, un, xm, ym, f(3)
      type(rigid_velocity_t) :: rv
      integer(ip), allocatable :: held(:)
      ! blocks held by BOUNDARY XVEL / YVEL at corners: their held directions
      ! carry a reaction, not an unbalanced force (as the cycle reports it)
      allocate (held(max(1_ip, geo%blocks%n)))
      held = 0
      if (rigid_velocity_present(bnd, geo)) then
         call rigid_velocity_build(bnd, geo, rv)
         do j = 1, rv%nblk
            held(rv%blk(j)) = j
         end do
      end if
      nb = 0
      nc = 0
      ncor = 0
      nd = 0
      nrigid = 0
      nfree = 0
      bmin = 0; bmax = 0; bvel = 0; bdis = 0; bfor = 0
      cfn = 0; cfnmin = 0; cfs = 0; cus = 0; cun = 0
      mmin = huge(1.0_wp); mmax = -huge(1.0_wp); msum = 0.0_wp
      vel = -1.0_wp; dis = -1.0_wp; for = -1.0_wp
      fn = -huge(1.0_wp); fnmin = huge(1.0_wp); fs = -1.0_wp; us = -1.0_wp
      un = -huge(1.0_wp)
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         if (.not. in_range(geo%blocks%xc(b), geo%blocks%yc(b), range)) cycle
         nb = nb + 1
         associate (blk => geo%blocks)
            msum = msum + blk%mass(b)
            if (blk%mass(b) < mmin) then
               mmin = blk%mass(b); bmin = b
            end if
            if (blk%mass(b) > mmax) then
               mmax = blk%mass(b); bmax = b
            end if
            ! a zoned (FDEF) block moves by its gridpoints (the zone lines of
            ! PRINT MAX): its block velocity, displacement and force are unused
            if (blk%nzone(b) > 0) cycle
            nrigid = nrigid + 1
            if (hypot(blk%vx(b), blk%vy(b)) > vel) then
               vel = hypot(blk%vx(b), blk%vy(b)); bvel = b
            end if
            if (hypot(blk%ux(b), blk%uy(b)) > dis) then
               dis = hypot(blk%ux(b), blk%uy(b)); bdis = b
            end if
            ! unbalanced force of a free block: contact sum + weight + LOAD
            ! (a fixed block's sum is its reaction, not out of balance)
            if (.not. blk%fixed(b)) then
               nfree = nfree + 1
               f = [blk%fx(b) + blk%mass(b)*grav(1) + blk%lx(b), &
                    blk%fy(b) + blk%mass(b)*grav(2) + blk%ly(b), blk%fm(b)]
               if (held(b) > 0) f = rigid_velocity_free_force(rv, bnd, geo, held(b), b, &
                                                              blk%mass(b), blk%inertia(b), f)
               if (hypot(f(1), f(2)) > for) then
                  for = hypot(f(1), f(2))
                  bfor = b
               end if
            end if
         end associate
      end do
      do c = 1, geo%corners%n
         if (.not. geo%corners%live(c)) cycle
         if (in_range(geo%corners%x(c), geo%corners%y(c), range)) ncor = ncor + 1
      end do
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         if (.not. in_range(geo%contacts%x(c), geo%contacts%y(c), range)) cycle
         nc = nc + 1
         associate (st => geo%contacts%state)
            if (st%fn(c) > fn) then
               fn = st%fn(c); cfn = c
            end if
            if (st%fn(c) < fnmin) then
               fnmin = st%fn(c); cfnmin = c
            end if
            if (abs(st%fs(c)) > fs) then
               fs = abs(st%fs(c)); cfs = c
            end if
            if (abs(st%us(c)) > us) then
               us = abs(st%us(c)); cus = c
            end if
            if (st%un(c) > un) then
               un = st%un(c); cun = c
            end if
         end associate
      end do
      do d = 1, geo%domains%n
         if (.not. geo%domains%live(d)) cycle
         if (present(range)) then
            call domain_centre(geo, d, xm, ym)
            if (.not. range%contains_point(xm, ym)) cycle
         end if
         nd = nd + 1
      end do
      call out%line('  QUANTITY                             VALUE  ENTITY       ID')
      call max_count_line(out, 'number of blocks', nb)
      call max_count_line(out, 'number of contacts', nc)
      call max_count_line(out, 'number of corners', ncor)
      call max_count_line(out, 'number of domains', nd)
      if (nb > 0) then
         call max_value_line(out, 'block mass, minimum', mmin, 'block', bmin)
         call max_value_line(out, 'block mass, average', msum/real(nb, wp), '', 0)
         call max_value_line(out, 'block mass, maximum', mmax, 'block', bmax)
      end if
      if (nrigid > 0) then
         call max_value_line(out, 'max block velocity', vel, 'block', bvel)
         call max_value_line(out, 'max block displacement', dis, 'block', bdis)
         ! every block FIXed: no force is out of balance (before: -1, the
         ! search's start)
         if (nfree > 0) call max_value_line(out, 'max unbalanced force', for, 'block', bfor)
         if (nfree == 0) call out%line('  max unbalanced force                 none' &
                                       //'  (every block is FIXed)')
      end if
      if (nc > 0) then
         call max_value_line(out, 'max normal force', fn, 'contact', cfn)
         call max_value_line(out, 'min normal force', fnmin, 'contact', cfnmin)
         call max_value_line(out, 'max |shear force|', fs, 'contact', cfs)
         call max_value_line(out, 'max |shear displacement|', us, 'contact', cus)
         call max_value_line(out, 'max normal displacement', un, 'contact', cun)
      end if
   end subroutine print_max

   !> PRINT STATUS: the global state of the problem.
   subroutine print_status(model, out)
      type(model_t), intent(in) :: model
      type(output_t), intent(in) :: out
      character(len=120) :: value
      integer(ip) :: nc, nd, ncor
      nc = 0
      nd = 0
      ncor = 0
      if (model%geometry%contacts%n > 0) &
         nc = count(model%geometry%contacts%live(1:model%geometry%contacts%n))
      if (model%geometry%domains%n > 0) &
         nd = count(model%geometry%domains%live(1:model%geometry%domains%n))
      if (model%geometry%corners%n > 0) &
         ncor = count(model%geometry%corners%live(1:model%geometry%corners%n))
      value = '(none)'
      if (allocated(model%heading)) then
         if (len_trim(model%heading) > 0) value = model%heading
      end if
      call status_pair(out, 'heading', trim(value))
      write (value, '(i0)') geometry_live_blocks(model%geometry)
      call status_pair(out, 'blocks', trim(value))
      write (value, '(i0)') nc
      if (.not. model%geometry%contacts_valid .and. model%geometry%block_created) &
         value = trim(value)//' (out of date: blocks changed since the last update)'
      call status_pair(out, 'contacts', trim(value))
      write (value, '(i0)') ncor
      call status_pair(out, 'corners', trim(value))
      write (value, '(i0)') nd
      call status_pair(out, 'domains', trim(value))
      call status_pair(out, 'time', format_real(model%mech%time))
      write (value, '(i0)') model%mech%step
      call status_pair(out, 'cycles', trim(value))
      call status_pair(out, 'time step', format_real(model%mech%dt))
      select case (model%mech%damping)
      case (damping_none)
         value = 'none'
      case (damping_auto)
         value = 'auto (adaptive), factor '//format_real(model%mech%auto_fac)
      case (damping_local)
         value = 'local (extension), alpha '//format_real(model%mech%local_alpha)
      case (damping_rayleigh)
         value = 'Rayleigh, fraction of critical '//format_real(model%mech%rayleigh_fcrit) &
                 //' at frequency '//format_real(model%mech%rayleigh_freq)
         if (.not. model%mech%rayleigh_stiff) value = trim(value)//' (mass only)'
         if (.not. model%mech%rayleigh_mass) value = trim(value)//' (stiffness only)'
      case default
         value = 'unknown'
      end select
      call status_pair(out, 'damping', trim(value))
      call status_pair(out, 'gravity (x, y)', format_real(model%gravity(1))//' '// &
                format_real(model%gravity(2)))
      call status_pair(out, 'max unbalanced force', format_real(model%mech%unbalanced))
      if (model%bound%fup) then
         value = 'FUP: tractions on the current boundary (default)'
      else
         value = '-FUP: fixed forces'
      end if
      call status_pair(out, 'boundary stress (SET)', trim(value))
      write (value, '(i0,a,i0,a)') model%hist%n, ' variable(s), ', model%hist%nsample, &
         ' sample(s)'
      call status_pair(out, 'histories', trim(value))
      write (value, '(i0,a)') model%geometry%jplot%n, ' segment(s) recorded'
      if (model%geometry%jplot%on) then
         call status_pair(out, 'JPLOT', 'recording, '//trim(value))
      else
         call status_pair(out, 'JPLOT', 'off, '//trim(value))
      end if
      call print_settings(model, out)
   end subroutine print_status

   !> The settings of ROUND, EDGE, FRACTION and SET with their current values
   !> (defaults of UDEC manual (ICG1.5, 1989), Section 4.5, where not given):
   !> the end of PRINT STATUS, and what SET alone prints.
   subroutine print_settings(model, out)
      type(model_t), intent(in) :: model
      type(output_t), intent(in) :: out
      type(fluid_t) :: fresh_fluid
      type(thermal_t) :: fresh_thermal
      character(len=:), allocatable :: value
      associate (geo => model%geometry, mech => model%mech)
         call status_pair(out, 'ROUND', format_real(geo%round))
         value = format_real(geo%edge_min)
         if (.not. geo%edge_set) value = value//' (twice the rounding)'
         call status_pair(out, 'EDGE', value)
         call status_pair(out, 'FRACTION', format_real(mech%frac_block)//' '// &
                          format_real(mech%frac_zone)// &
                   ' '//format_real(mech%frac_fluid)//' (blocks, zones, fluid)')
         call status_pair(out, 'SET CSCAN DSCAN UPCON', itoa(int(mech%cscan))//' '// &
                          itoa(int(mech%dscan))// &
                   ' '//itoa(int(mech%nupcon)))
         if (mech%ovtol > 0.0_wp) then
            call status_pair(out, 'SET OVTOL', format_real(mech%ovtol))
         else
            call status_pair(out, 'SET OVTOL', &
                             format_real(0.5_wp*geo%round)//' (half the rounding)')
         end if
         if (mech%clemin > 0.0_wp) then
            call status_pair(out, 'SET CLEMIN', format_real(mech%clemin))
         else
            call status_pair(out, 'SET CLEMIN', '1/10 of the mean contact length')
         end if
         if (geo%jmat_default > 0) then
            value = itoa(int(geo%jmat_default))
         else
            value = 'the material of a block beside the contact'
         end if
         call status_pair(out, 'SET JMATDF JCONDF', value//', '//itoa(int(geo%jcons_default)))
      end associate
      if (allocated(model%fluid)) then
         call fluid_settings(model%fluid)
      else
         call fluid_settings(fresh_fluid)
      end if
      if (allocated(model%thermal)) then
         call thermal_settings(model%thermal)
      else
         call thermal_settings(fresh_thermal)
      end if
   contains
      subroutine fluid_settings(f)
         type(fluid_t), intent(in) :: f
         call status_pair(out, 'SET CAPRATIO PTOL', &
                          format_real(f%capratio)//' '//format_real(f%ptol))
         call status_pair(out, 'SET EFF SFLOW YWTABLE', trim(merge('EFF ', '-EFF', f%eff))//' '// &
                   trim(merge('SFLOW ', '-SFLOW', f%sflow))//' '//format_real(f%ywtab))
      end subroutine fluid_settings
      subroutine thermal_settings(t)
         type(thermal_t), intent(in) :: t
         call status_pair(out, 'SET NMECH NTHER', itoa(int(t%nmech))//' '//itoa(int(t%nther)))
      end subroutine thermal_settings
   end subroutine print_settings

   !> One line of PRINT STATUS: the label in 24 columns, then the value.
   subroutine status_pair(out, label, text)
      type(output_t), intent(in) :: out
      character(len=*), intent(in) :: label, text
      character(len=24) :: l
      l = label
      call out%line('  '//l//text)
   end subroutine status_pair

   !> PRINT HIST: without ids, the list of history variables; with ids, the
   !> samples, time first, one column per variable.
   subroutine print_history(hist, ids, out)
      type(history_t), intent(in) :: hist
      integer, intent(in) :: ids(:)
      type(output_t), intent(in) :: out
      integer, allocatable :: use(:)
      character(len=:), allocatable :: text
      character(len=14) :: column
      integer :: i, n
      integer(ip) :: s, first
      if (size(ids) == 0) then
         call history_list(hist, out)
         return
      end if
      call defined_ids(hist, ids, 'PRINT HIST', out, use)
      n = size(use)
      if (n == 0) return
      ! a deferred-length assignment would shrink `text`: assign into a slice
      allocate (character(len=14*(n + 1)) :: text)
      text(:) = '          TIME'
      do i = 1, n
         write (column, '(i0,1x,a)') use(i), trim(hist_keyword(hist%kind(use(i))))
         text(14*i + 1:14*i + 14) = adjustr(column)
      end do
      call out%line(text)
      if (hist%nsample == 0) call out%line('  (no samples recorded)')
      ! rows start at the first sample of the earliest requested history: a
      ! HISTORY given after a RESTART prints its own samples, not a '-' for
      ! every sample taken before it existed
      first = hist%nsample + 1
      do i = 1, n
         first = min(first, history_first(hist, use(i)))
      end do
      do s = max(first, 1_ip), hist%nsample
         text(1:14) = fmt_real(hist%time(s))
         do i = 1, n
            if (s < history_first(hist, use(i))) then
               ! not defined yet at this sample (HISTORY given later)
               text(14*i + 1:14*i + 14) = '             -'
            else
               text(14*i + 1:14*i + 14) = fmt_real(hist%values(use(i), s))
            end if
         end do
         call out%line(text)
      end do
      ! which variable each column is (the manual's HISTORY keyword) and where
      ! it is taken; after the table, so the header stays the first line
      do i = 1, n
         call out%line('  column '//history_place(hist, use(i)))
      end do
   end subroutine print_history

   !> "3 XDIS at (1.5, 2) gridpoint 12": history v by the manual's keyword with
   !> where it is taken (corner / gridpoint / zone / contact / block).
   function history_place(hist, v) result(text)
      type(history_t), intent(in) :: hist
      integer, intent(in) :: v
      character(len=:), allocatable :: text
      character(len=24) :: id
      character(len=:), allocatable :: word
      write (id, '(i0)') hist%entity(v)
      text = itoa(v)//' '//trim(hist_keyword(hist%kind(v)))
      word = entity_kind(hist%kind(v))
      select case (word)
      case ('contact', 'block')
         text = text//' '//word//' '//trim(id)
      case ('corner', 'gridpoint', 'zone')
         text = text//' at ('//trim(adjustl(fmt_real(hist%px(v))))//', '// &
                trim(adjustl(fmt_real(hist%py(v))))//') '//word//' '//trim(id)
      end select
   end function history_place

   !> What the ENTITY id of a history kind numbers.
   function entity_kind(kind) result(word)
      integer, intent(in) :: kind
      character(len=:), allocatable :: word
      select case (kind)
      case (hist_ndis, hist_sdis, hist_nstr, hist_sstr, hist_srat)
         word = 'contact'
      case (hist_bfx, hist_bfy, hist_bfm)
         word = 'block'
      case (hist_xvel, hist_yvel, hist_xdis, hist_ydis)
         word = 'corner'
      case (hist_gxvel, hist_gyvel, hist_gxdis, hist_gydis)
         word = 'gridpoint'
      case (hist_sxx, hist_sxy, hist_syy)
         word = 'zone'
      case default
         word = '-'
      end select
   end function entity_kind

   !> The list of history variables: id, type, entity, point asked, point used.
   subroutine history_list(hist, out)
      type(history_t), intent(in) :: hist
      type(output_t), intent(in) :: out
      character(len=100) :: text
      character(len=13) :: kind_col
      integer :: i
      if (hist%n == 0) then
         call out%line('  no histories defined')
         return
      end if
      write (text, '(a,i0,a,i0)') '  histories sampled every ', hist%ncyc, &
         ' cycles; samples: ', hist%nsample
      call out%line(text)
      call out%line('    HIST  TYPE     ENTITY             X             Y' // &
                    '        X-USED        Y-USED         KIND')
      do i = 1, hist%n
         write (text, '(i8,2x,a5,i10,4a)') i, hist_keyword(hist%kind(i)), hist%entity(i), &
            fmt_real(hist%x(i)), fmt_real(hist%y(i)), fmt_real(hist%px(i)), fmt_real(hist%py(i))
         kind_col = entity_kind(hist%kind(i))
         kind_col = adjustr(kind_col)
         call out%line(trim(text)//kind_col)
      end do
   end subroutine history_list

   !> Requested history ids that exist; a note for each that does not.
   subroutine defined_ids(hist, ids, what, out, use)
      type(history_t), intent(in) :: hist
      integer, intent(in) :: ids(:)
      character(len=*), intent(in) :: what
      type(output_t), intent(in) :: out
      integer, allocatable, intent(out) :: use(:)
      integer :: i
      character(len=100) :: text
      allocate (use(0))
      do i = 1, size(ids)
         if (ids(i) >= 1 .and. ids(i) <= hist%n) then
            use = [use, ids(i)]
         else
            write (text, '(a,a,i0,a,i0,a)') what, ': history ', ids(i), &
               ' is not defined (', hist%n, ' defined)'
            call out%line('*** '//trim(text))
         end if
      end do
   end subroutine defined_ids

   !> PRINT HMAX n..: maximum and minimum of each history with their times
   !> (all histories without ids).
   subroutine print_history_max(hist, ids, out)
      type(history_t), intent(in) :: hist
      integer, intent(in) :: ids(:)
      type(output_t), intent(in) :: out
      integer, allocatable :: use(:)
      integer :: i, v, imax, imin
      integer(ip) :: s1
      character(len=100) :: text
      if (size(ids) == 0) then
         use = [(i, i=1, hist%n)]
         if (hist%n == 0) call out%line('  no histories defined')
      else
         call defined_ids(hist, ids, 'PRINT HMAX', out, use)
      end if
      if (size(use) == 0) return
      call out%line('    HIST  TYPE        MAXIMUM       AT TIME       MINIMUM       AT TIME')
      if (hist%nsample == 0) then
         call out%line('  (no samples recorded)')
         return
      end if
      do i = 1, size(use)
         v = use(i)
         ! over the samples the variable has (a later HISTORY starts later)
         s1 = history_first(hist, v)
         if (s1 > hist%nsample) then
            write (text, '(i8,2x,a5,a)') v, hist_keyword(hist%kind(v)), '   (no samples yet)'
            call out%line(text)
            cycle
         end if
         imax = int(s1) - 1 + maxloc(hist%values(v, s1:hist%nsample), 1)
         imin = int(s1) - 1 + minloc(hist%values(v, s1:hist%nsample), 1)
         write (text, '(i8,2x,a5,4a)') v, hist_keyword(hist%kind(v)), &
            fmt_real(hist%values(v, imax)), fmt_real(hist%time(imax)), &
            fmt_real(hist%values(v, imin)), fmt_real(hist%time(imin))
         call out%line(text)
      end do
   end subroutine print_history_max

   !> PRINT PROPERTY <kind ...>: all properties, or those of each kind.
   subroutine do_property(model, parsed, k, nsub, out)
      type(model_t), intent(in) :: model
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k, nsub
      type(output_t), intent(in) :: out
      integer :: j
      character(len=:), allocatable :: kind
      if (nsub == 0) then
         call print_properties(model, out)
         return
      end if
      do j = k + 1, k + nsub
         kind = parsed%items(j)%name
         call out%line('')
         call out%line('  '//kind//' properties')
         call print_properties(model, out, kind_properties(kind))
      end do
   end subroutine do_property

   !> Property ids of each PRINT PROPERTY kind (manual Section 4.5 PROPERTY).
   function kind_properties(kind) result(ids)
      character(len=*), intent(in) :: kind
      integer, allocatable :: ids(:)
      select case (kind)
      case ('BLOCKS')
         ids = [prop_bulk, prop_shear, prop_density, prop_cohesion, prop_friction, &
               prop_tensile, prop_dilation, prop_tf, prop_hbs, prop_hbm, prop_ucs]
      case ('BOUNDARY')
         ids = [prop_bulk, prop_shear, prop_density]
      case ('CABLE')
         ids = [prop_shear, prop_bulk, prop_density, prop_ycomp, prop_yield, prop_jks, &
               prop_jcoh]
      case ('CONTACTS')
         ids = [prop_kn, prop_ks, prop_ccohesion, prop_cperm, prop_cdilation, &
               prop_cfriction, prop_ctensile]
      case ('FLUID')
         ids = [prop_cperm, prop_jperm, prop_azero, prop_ares]
      case ('JOINT')
         ids = [prop_azero, prop_ares, prop_jkn, prop_jks, prop_jcoh, prop_jdil, &
               prop_jfric, prop_jperm, prop_jtensile, prop_jen, prop_jes, prop_jif, prop_jr]
      case ('REINFORCEMENT')
         ids = [prop_rastiff, prop_rsstiff, prop_rlength, prop_ruaxial, &
               prop_rushear, prop_rrfac, prop_rsexp, prop_raexp]
      case ('STRUCTURAL')
         ids = [prop_density, prop_bulk, prop_shear, prop_kn, prop_ks, prop_ccohesion, &
               prop_cfriction, prop_ctensile]
      case ('THERMAL')
         ids = [prop_specheat, prop_thexp, prop_xcond, prop_ycond]
      case default
         allocate (ids(0))
      end select
   end function kind_properties

   !> STRESS xl xu yl yu nx ny: the same as PRINT STRESS (manual 4.5), with
   !> the same file STRESS.
   subroutine do_stress(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      associate (model => ctx%model, out => ctx%out)
         call stress_grid_check(parsed, 1, error, 'STRESS')
         if (allocated(error)) return
         call print_stress_grid(model, parsed%real_at(1, 1), parsed%real_at(1, 2), &
                                parsed%real_at(1, 3), parsed%real_at(1, 4), parsed%int_at(1, 5), &
                                parsed%int_at(1, 6), out, stress_file_name, error)
      end associate
   end subroutine do_stress

   subroutine run_print(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      call handle_print(ctx%model, parsed, ctx%out, error, ctx%cycle)
   end subroutine run_print

end module commands_print
