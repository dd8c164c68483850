!> The save file (SAVE / RESTART, manual Section 4.5): every group, dataset and
!> attribute name of the HDF5 file, and the schema version.
!>
!> One walker per type (`walk_*` below) lists that type's fields once; the
!> same list writes the file (SAVE) and reads it back (RESTART), so a field
!> cannot be written and forgotten on reading or the other way round.
!>
!> File layout (h5dump shows these names):
!>   /                 @format, @schema_version, @program, @program_version,
!>                     @heading, @gravity, @cycled
!>   /materials        @nmat, @property_names, value(45, nmat), given(45, nmat)
!>   /geometry         the settings of geometry_t as attributes (@round, @rng_state, ...)
!>   /geometry/blocks, corners, contacts, contacts/state, domains, pending, tunnels, jplot,
!>                     gridpoints, zones (schema 2); (schema 11) addr of blocks,
!>                     corners, contacts, domains, gridpoints, zones, @ia_mfree,
!>                     @ia_outer, @ia_njunk, ia_junk_addr, ia_junk_len (1989
!>                     addresses, model_address; older files get them afresh)
!>                     @n and one dataset per array field (entries 1..n)
!>   /mechanics        mechanics_t as attributes
!>   /history          @n, @nsample, ..., kind(n), ..., time(nsample), values(n, nsample),
!>                     first_sample(n) (schema 4; older files: 0, i.e. all samples)
!>   /boundary         (schema 2) @n, @corners_seen, @t_start, one dataset per array of
!>                     boundary_t; table1, table2 (HREAD): @heading, @np, @dt, values(np);
!>                     zpress (SET ZPRESS): @n, @h_next, @freq_next, @tload_next,
!>                     x y rad pz h freq tload nzone (n), @nz, zone src (nz);
!>                     (schema 4) vis, vmat (viscous boundaries); (schema 10) @fup
!>                     (SET FUP), sxx_prev ... dsyy_next, end_prev, end_next (boundary
!>                     stresses kept as tractions, model_boundary)
!>   /be               (schema 6) BE settings and link (model_be; the matrix is
!>                     rebuilt from it at the next CYCLE)
!>   mechanics         (schema 5) @fxhis, @fyhis (HISTORY XHIS / YHIS)
!>   /                 (schema 7) @has_fluid; /fluid when true: FLUID and SET settings as
!>                     attributes, @nd, p fixed vol xd yd (nd), @nc, aperture q bnd_code
!>                     bnd_p bnd_g cdom1 cdom2 (nc) (model_fluid)
!>   /                 (schema 8) @structures: the model has structural elements; then
!>   /structures       nodes, elements, interfaces (model_structures): @n and one
!>                     dataset per array field
!>   /                 (schema 9) @has_thermal; /thermal when true: RUN / SET settings as
!>                     attributes, @ng, temp fixed dtacc (ng), @nrec, @nset, rec_kind
!>                     rec_id rec_p1 rec_p2 rec_t0 rec_set (nrec), @nthis @ntcyc
!>                     @this_type this_gp this_x this_y (nthis), @nsamp samp_time (nsamp)
!>                     samp_val (20 nsamp) (model_thermal)
!>   /thermal          (schema 13) @nc ctemp cfixed cdtacc (nc), @nb btemp bfixed bdtacc
!>                     (nb): temperatures of the corners and centroids of blocks without
!>                     zones (Fig. 7-4); this_kind (nthis): 0 gridpoint, 1 corner, 2 centroid
!>   /boundary         (schema 11) ff (BOUNDARY FF)
!>   /ffield           (schema 11) the free-field column (model_ffield): @on @np @yl @yu
!>                     @dy @base_*, vx vy ux uy fx fy (np), mat cons sxx0 sxy0 (np - 1),
!>                     zones (as /geometry/zones)
!>   /                 (schema 12) @has_tables; /tables when true: TABLE (model_tables):
!>                     @len (10), @ntot, @x @y (ntot)
!>   /geometry/blocks  (schema 12) sdef exx eyy exy dxx dyy dxy sxx syy sxy qxx qyy qxy
!>                     bstate (simply-deformable blocks); /mechanics (schema 12)
!>                     @internal_fcrit @internal_freq @internal_mass @internal_stiff
!>   /                 (schema 12) @has_reinforcement; /reinforcement when true
!>                     (model_reinforcement): @ncable, groups reinf, cable_nodes,
!>                     cable_elements, each @n and one dataset per array field
!>   /geometry/contacts/state (schema 14) ud, the dilation each contact has
!>                     ridden up (older files: 0)
!>   /mechanics        (schema 15) @local_alpha, DAMP LOCAL's fraction (older
!>                     files: 0.8, unused unless @damping is 3)
!>   /geometry         (schema 16) @nrefused_keys, refused_keys (6 x n: block,
!>                     reason, path ends), the refused cuts already counted
!>                     (older files: none)
!>   /mechanics        (schema 17) @search_current, @search_sizes (3),
!>                     @search_margin: the last search for new contacts
!>                     still stands (engine_cycle search_skippable), so a
!>                     restart skips or makes the CYCLE's opening search as
!>                     the run it continues (older files: false, a search)
!>   /mechanics        (schema 18) @probe_time, @probe_w, @probe_wref: DAMP
!>                     AUTO's probe after a load change on a zoned model
!>                     (engine_cycle damping_probe), so a restart between the
!>                     load and its balance damps as the run it continues
!>                     (older files: -1, 0, 0: no probe)
!> Each dataset carries @allocated_size, the capacity of the array in memory.
!>
!> Adding a field to model_t or one of its parts:
!>   1. add one line to the type's walker, with `since=` the new schema version;
!>   2. raise `schema_version` (older files still load: a field newer than the
!>      file keeps its default value, arrays come back zero-filled);
!>   3. extend the filler and the comparison in tests/unit/test_save_restart.f90
!>      (its size check fails until you do).
!> Renaming or removing a field needs a real conversion of older files here.
module io_schema
   use model_address, only: address_ensure, address_forget_rows
   use core_kinds, only: ip, wp
   use core_error, only: error_t, set_error
   use core_files, only: file_kind, file_kind_name, kind_regular, kind_unknown
   use core_version, only: udec_version, udec_name
   use model_state, only: model_t
   use model_materials, only: material_table_t
   use model_properties, only: property_names
   use model_geometry, only: geometry_t, block_list_t, corner_list_t, contact_list_t, &
                             joint_state_t, domain_list_t, pending_list_t, tunnel_list_t, &
                             jplot_list_t, joint_state_jcons3, joint_state_ud, block_sdef_fields, &
                             contact_corner1, contact_corner2, contact_edge1, contact_edge2
   use model_zones, only: gridpoint_list_t, zone_list_t
   use model_ffield, only: ffield_t
   use model_mechanics, only: mechanics_t
   use model_history, only: history_t, hist_names
   use model_boundary, only: boundary_t, boundary_table_t, zpress_t
   use model_be, only: be_t
   use model_reinforcement, only: reinforcement_t, reinf_list_t, cable_node_list_t, &
                                  cable_element_list_t
   use model_structures, only: structure_t, structure_node_list_t, structure_element_list_t, &
                               structure_interface_list_t
   use model_fluid, only: fluid_t
   use model_thermal, only: thermal_t, max_thist
   use io_hdf5_stream, only: stream_t, stream_write
   use io_posix, only: posix_getpid, posix_unlink
   use core_files, only: file_rename, check_output_file, temporary_name
   use core_interrupt, only: interrupt_temporary
   implicit none
   private
   public :: schema_version, save_format_name, io_save_model, io_load_model

   !> Version of the file layout; raise it whenever a field is added.
   integer, parameter :: schema_version = 18
   character(len=*), parameter :: save_format_name = 'udec save file'

contains

   !> The meaning of each integer code the file holds, as an attribute
   !> `codes` on its dataset (`damping_codes` on /mechanics), and the unit of
   !> the main real datasets as an attribute `unit`, for readers of the file
   !> outside udec (h5dump, h5py). Written, never read back: both are fixed
   !> by the schema version.
   subroutine annotate_codes(s)
      type(stream_t), intent(inout) :: s
      character(len=*), parameter :: cons = 'CONS of the manual (Section 4.5 CHANGE): 0 null (excavated), '// &
         '1 linearly elastic, 3 elastic/plastic Mohr-Coulomb (zones), 4 elastic/brittle Griffith (SDEF)'
      character(len=*), parameter :: bc = 'per direction, as PRINT BOUNDARY STATE: 0 free, 1 stress or load, '// &
         '3 viscous, 4 velocity'
      call s%annotate('/geometry/blocks/cons', 'codes', cons)
      call s%annotate('/geometry/blocks/fixed', 'codes', '0 free, 1 velocities held (FIX)')
      call s%annotate('/geometry/blocks/fdef', 'codes', '0 rigid, 1 fully deformable (zoned)')
      call s%annotate('/geometry/contacts/kind', 'codes', '1 corner-corner, 2 corner of block1 on an '// &
         'edge of block2, 3 edge of block1 on a corner of block2 (an edge is named by its first corner, clockwise)')
      call s%annotate('/geometry/contacts/jcons', 'codes', 'JCONS of the manual (Section 4.5 CHANGE): '// &
         '1 point contact Mohr-Coulomb, 2 joint area contact Mohr-Coulomb, 3 continuously yielding, '// &
         '5 as 2 with a fracture flag')
      call s%annotate('/geometry/contacts/state/flags', 'codes', 'bits: 1 at slip, 2 open (tension failure), '// &
         '4 fractured (JCONS 5: cohesion and tension ignored)')
      call s%annotate('/geometry/zones/state', 'codes', '0 elastic, 1 at failure now, 2 failed in the past, '// &
         '3 tension failure')
      call s%annotate('/geometry/gridpoints/vfix', 'codes', 'bits: 1 x velocity prescribed, 2 y velocity '// &
         'prescribed (BOUNDARY XVEL / YVEL)')
      call s%annotate('/boundary/ix', 'codes', 'x '//bc)
      call s%annotate('/boundary/iy', 'codes', 'y '//bc)
      call s%annotate('/boundary/vis', 'codes', 'bits: 1 viscous in x, 2 viscous in y (BOUNDARY XVISC / YVISC)')
      call s%annotate('/boundary/hx', 'codes', 'x history: 0 constant, 1 linear, 2 sine, 3 cosine, '// &
         '11 table 1, 12 table 2 (HREAD)')
      call s%annotate('/boundary/hy', 'codes', 'y history: 0 constant, 1 linear, 2 sine, 3 cosine, '// &
         '11 table 1, 12 table 2 (HREAD)')
      call s%annotate('/mechanics', 'damping_codes', 'damping: 0 none, 1 automatic (DAMP AUTO), '// &
         '2 Rayleigh (DAMP f c), 3 local (DAMP LOCAL alpha)')
      call s%annotate('/history/kind', 'codes', 'index into the attribute kind_names of this group')
      call s%annotate('/fluid/bnd_code', 'codes', '0 open, 1 pressure given (BOUNDARY PP), 2 impermeable')
      call s%annotate('/thermal/rec_kind', 'codes', '1 convection, 2 flux, 3 radiation, 4 source (THAPP)')
      call s%annotate('/structures/interfaces/flags', 'codes', 'bits: 1 broken (tension), 2 at slip')
      call s%annotate('/structures/nodes/fix', 'codes', 'bits: 1 x fixed, 2 y fixed, 4 rotation fixed')
      ! units: udec takes any consistent units (the manual's decks use SI or
      ! MPa-based sets), so each dataset names its dimension and its SI unit
      call units('/geometry/blocks', [character(len=8) :: 'xc', 'yc', 'xmin', 'xmax', 'ymin', 'ymax', &
                 'ux', 'uy'], 'length (m in SI)')
      call units('/geometry/blocks', [character(len=8) :: 'vx', 'vy'], 'length/time (m/s in SI)')
      call units('/geometry/blocks', [character(len=8) :: 'vr'], 'radians/time (rad/s)')
      call units('/geometry/blocks', [character(len=8) :: 'rot'], 'radians')
      call units('/geometry/blocks', [character(len=8) :: 'fx', 'fy', 'lx', 'ly'], &
                 'force per unit thickness (N/m in SI)')
      call units('/geometry/blocks', [character(len=8) :: 'fm'], 'moment per unit thickness (N m/m in SI)')
      call units('/geometry/blocks', [character(len=8) :: 'area'], 'length^2 (m2 in SI)')
      call units('/geometry/blocks', [character(len=8) :: 'mass'], 'mass per unit thickness (kg/m in SI)')
      call units('/geometry/blocks', [character(len=8) :: 'sxx', 'syy', 'sxy'], 'stress (Pa in SI)')
      call units('/geometry/corners', [character(len=8) :: 'x', 'y', 'rx', 'ry', 'radius', 'ux', 'uy'], &
                 'length (m in SI)')
      call units('/geometry/contacts', [character(len=8) :: 'x', 'y', 'length', 'gap'], 'length (m in SI)')
      call units('/geometry/contacts/state', [character(len=8) :: 'fn', 'fs'], &
                 'force per unit thickness (N/m in SI); fn compression positive')
      call units('/geometry/contacts/state', [character(len=8) :: 'un', 'us'], &
                 'length (m in SI); un opening positive')
      call units('/geometry/gridpoints', [character(len=8) :: 'x', 'y', 'ux', 'uy'], 'length (m in SI)')
      call units('/geometry/gridpoints', [character(len=8) :: 'vx', 'vy'], 'length/time (m/s in SI)')
      call units('/geometry/gridpoints', [character(len=8) :: 'fx', 'fy'], 'force per unit thickness (N/m in SI)')
      call units('/geometry/zones', [character(len=8) :: 'sxx', 'sxy', 'syy', 'szz'], &
                 'stress (Pa in SI); compression negative')
      call units('/boundary', [character(len=8) :: 'fx', 'fy', 'dfx', 'dfy'], 'force per unit thickness (N/m in SI)')
      call units('/history', [character(len=8) :: 'time'], 'time (s in SI)')
      call s%annotate('/history/values', 'unit', 'each variable in the unit of its kind '// &
                      '(kind_names; PRINT HIST and EXPORT HISTORY name them)')
   contains
      subroutine units(group, names, text)
         character(len=*), intent(in) :: group, names(:), text
         integer :: i
         do i = 1, size(names)
            call s%annotate(group//'/'//trim(names(i)), 'unit', text)
         end do
      end subroutine units
   end subroutine annotate_codes

   !> Write `model` to `filename`. The file is written under a temporary name
   !> in the same folder and renamed over `filename` only when complete, so a
   !> failed SAVE (disk full, no permission) leaves an older file intact.
   subroutine io_save_model(model, filename, error)
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: filename
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: copy
      type(stream_t) :: s
      character(len=:), allocatable :: temporary
      character(len=32) :: pid
      character(len=256) :: message
      integer :: unit, ios
      logical :: removed, renamed
      ! a folder, device or FIFO is refused before anything is written
      ! (the rename below would replace it by a regular file)
      call check_output_file('', filename, error)
      if (allocated(error)) return
      ! the walker reads and writes through one interface (intent inout)
      copy = model
      write (pid, '(i0)') posix_getpid()
      temporary = temporary_name(filename)//trim(pid)
      ! a plain open first: its message names the cause (no such folder,
      ! permission denied) better than HDF5's
      open (newunit=unit, file=temporary, status='replace', action='write', &
            iostat=ios, iomsg=message)
      if (ios /= 0) then
         call set_error(error, "cannot write save file '"//filename//"': "//trim(message))
         return
      end if
      close (unit, status='delete')
      ! removed by the signal handler if the program is made to quit meanwhile
      call interrupt_temporary(temporary)
      call s%create(temporary)
      if (.not. s%failed()) call walk_root(s, copy)
      if (.not. s%failed()) call annotate_codes(s)
      call s%close()
      call interrupt_temporary('')
      if (s%failed()) then
         removed = posix_unlink(temporary)
         call set_error(error, "cannot write save file '"//filename//"': "//s%message)
         return
      end if
      call file_rename(temporary, filename, renamed)
      if (.not. renamed) then
         removed = posix_unlink(temporary)
         call set_error(error, "cannot write save file '"//filename// &
                        "': renaming the finished temporary file onto it failed")
      end if
   end subroutine io_save_model

   !> Replace `model` by the one saved in `filename`. The file is read into a
   !> fresh model first: on any error `model` is left exactly as it was.
   subroutine io_load_model(model, filename, error)
      type(model_t), intent(inout) :: model
      character(len=*), intent(in) :: filename
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: fresh
      type(stream_t) :: s
      logical :: exists
      integer :: kind
      inquire (file=filename, exist=exists)
      if (.not. exists) then
         call set_error(error, "cannot read save file '"//filename//"': no such file")
         return
      end if
      ! a folder or a device (RESTART sub/dir) is named as such, not as a bad file
      kind = file_kind(filename)
      if (kind /= kind_regular .and. kind /= kind_unknown) then
         call set_error(error, "cannot read save file '"//filename//"': it is "// &
                        file_kind_name(kind)//', not a save file')
         return
      end if
      call s%open(filename)
      if (.not. s%failed()) call walk_root(s, fresh)
      call s%close()
      if (s%failed()) then
         call set_error(error, "cannot read save file '"//filename//"': "//s%message)
         return
      end if
      call move_model(fresh, model)
   end subroutine io_load_model

   !> model_t has no pointer components: intrinsic assignment is a deep copy.
   subroutine move_model(from, to)
      type(model_t), intent(inout) :: from
      type(model_t), intent(inout) :: to
      to = from
   end subroutine move_model

   !> Root: identification first (so a reader can refuse early), then the model.
   subroutine walk_root(s, m)
      type(stream_t), intent(inout) :: s
      type(model_t), intent(inout) :: m
      character(len=:), allocatable :: format, program, version
      integer :: file_version
      character(len=64) :: text
      format = save_format_name
      program = udec_name
      version = udec_version
      file_version = schema_version
      if (s%mode_is_read()) then
         if (.not. s%has_attr('format')) then
            if (.not. s%failed()) call s%fail('it is an HDF5 file but not a udec save file')
            return
         end if
      end if
      call s%text('format', format)
      if (s%failed()) return
      if (format /= save_format_name) then
         call s%fail('it is an HDF5 file but not a udec save file (format "'//format//'")')
         return
      end if
      call s%attr('schema_version', file_version)
      call s%text('program', program)
      call s%text('program_version', version)
      if (s%failed()) return
      if (file_version > schema_version) then
         write (text, '(a,i0,a,i0)') 'it has schema version ', file_version, &
            ', newer than the versions up to ', schema_version
         call s%fail(trim(text)//' that this udec ('//udec_version//') reads; it was '// &
                     'written by '//program//' '//version)
         return
      end if
      if (file_version < 1) then
         call s%fail('it has an invalid schema version')
         return
      end if
      s%version = file_version
      call walk_model(s, m)
   end subroutine walk_root

   subroutine walk_model(s, m)
      type(stream_t), intent(inout) :: s
      type(model_t), intent(inout) :: m
      logical :: present_structures
      logical :: has_fluid, has_thermal, has_tables, has_reinforcement
      call s%text('heading', m%heading)
      call s%attr('gravity', m%gravity)
      call s%attr('cycled', m%cycled)
      call s%begin_group('materials')
      call walk_materials(s, m%materials)
      call s%end_group()
      call s%begin_group('geometry')
      call walk_geometry(s, m%geometry)
      call s%end_group()
      call s%begin_group('mechanics')
      call walk_mechanics(s, m%mech)
      call s%end_group()
      call s%begin_group('history')
      call walk_history(s, m%hist)
      call s%end_group()
      ! schema 2: boundary conditions
      if (.not. (s%mode_is_read() .and. s%version < 2)) then
         call s%begin_group('boundary')
         call walk_boundary(s, m%bound)
         call s%end_group()
      end if
      ! schema 6: boundary-element far field
      if (.not. (s%mode_is_read() .and. s%version < 6)) then
         call s%begin_group('be')
         call walk_be(s, m%be)
         call s%end_group()
      end if
      ! schema 8: structural elements (an allocatable part: written only if present)
      if (.not. (s%mode_is_read() .and. s%version < 8)) then
         present_structures = allocated(m%structures)
         call s%attr('structures', present_structures, since=8)
         if (present_structures) then
            if (.not. allocated(m%structures)) allocate (m%structures)
            call s%begin_group('structures')
            call walk_structures(s, m%structures)
            call s%end_group()
         end if
      end if
      ! schema 7: joint fluid flow (an optional part: written only when present)
      has_fluid = allocated(m%fluid)
      call s%attr('has_fluid', has_fluid, since=7)
      if (has_fluid) then
         if (.not. allocated(m%fluid)) allocate (m%fluid)
         call s%begin_group('fluid')
         call walk_fluid(s, m%fluid)
         call s%end_group()
      end if
      ! schema 11: the free-field column (FFIELD)
      if (.not. (s%mode_is_read() .and. s%version < 11)) then
         call s%begin_group('ffield')
         call walk_ffield(s, m%ffield)
         call s%end_group()
      end if
      ! schema 12: TABLE (an optional part: written only when a table exists)
      has_tables = m%tables%ntot > 0
      call s%attr('has_tables', has_tables, since=12)
      if (has_tables) then
         call s%begin_group('tables')
         call s%attr('len', m%tables%len, since=12)
         call s%attr('ntot', m%tables%ntot, since=12)
         ! a few pairs: attributes of the group (no dataset objects)
         if (s%mode_is_read()) then
            if (s%failed()) return
            if (m%tables%ntot < 1 .or. any(m%tables%len < 0) .or. &
                m%tables%ntot /= sum(m%tables%len)) then
               call s%fail('/tables: the table lengths do not add up to @ntot')
               return
            end if
            if (allocated(m%tables%x)) deallocate (m%tables%x)
            if (allocated(m%tables%y)) deallocate (m%tables%y)
            allocate (m%tables%x(max(0_ip, m%tables%ntot)), m%tables%y(max(0_ip, m%tables%ntot)))
         end if
         call s%attr('x', m%tables%x(1:m%tables%ntot), since=12)
         call s%attr('y', m%tables%y(1:m%tables%ntot), since=12)
         call s%end_group()
      end if
      ! schema 9: heat conduction (an optional part: written only when present)
      has_thermal = allocated(m%thermal)
      call s%attr('has_thermal', has_thermal, since=9)
      if (has_thermal) then
         if (.not. allocated(m%thermal)) allocate (m%thermal)
         call s%begin_group('thermal')
         call walk_thermal(s, m%thermal)
         call s%end_group()
      end if
      ! schema 12: reinforcement (REINFORCE, CABLE; written only when present)
      has_reinforcement = allocated(m%reinforcement)
      call s%attr('has_reinforcement', has_reinforcement, since=12)
      if (has_reinforcement) then
         if (.not. allocated(m%reinforcement)) allocate (m%reinforcement)
         call s%begin_group('reinforcement')
         call walk_reinforcement(s, m%reinforcement)
         call s%end_group()
      end if
   end subroutine walk_model

   !> Reinforcement (model_reinforcement).
   subroutine walk_reinforcement(s, t)
      type(stream_t), intent(inout) :: s
      type(reinforcement_t), intent(inout) :: t
      call s%attr('ncable', t%ncable, since=12)
      call s%begin_group('reinf')
      call walk_reinf(s, t%reinf)
      call s%end_group()
      call s%begin_group('cable_nodes')
      call walk_cable_nodes(s, t%nodes)
      call s%end_group()
      call s%begin_group('cable_elements')
      call walk_cable_elements(s, t%elements)
      call s%end_group()
   end subroutine walk_reinforcement

   subroutine walk_reinf(s, d)
      type(stream_t), intent(inout) :: s
      type(reinf_list_t), intent(inout) :: d
      call s%attr('n', d%n, since=12)
      call s%field('material', d%material, d%n, since=12)
      call s%field('block1', d%block1, d%n, since=12)
      call s%field('block2', d%block2, d%n, since=12)
      call s%field('g1a', d%g1a, d%n, since=12)
      call s%field('g1b', d%g1b, d%n, since=12)
      call s%field('g2a', d%g2a, d%n, since=12)
      call s%field('g2b', d%g2b, d%n, since=12)
      call s%field('w1', d%w1, d%n, since=12)
      call s%field('w2', d%w2, d%n, since=12)
      call s%field('x1', d%x1, d%n, since=12)
      call s%field('y1', d%y1, d%n, since=12)
      call s%field('x2', d%x2, d%n, since=12)
      call s%field('y2', d%y2, d%n, since=12)
      call s%field('ax', d%ax, d%n, since=12)
      call s%field('ay', d%ay, d%n, since=12)
      call s%field('tx', d%tx, d%n, since=12)
      call s%field('ty', d%ty, d%n, since=12)
      call s%field('dx', d%dx, d%n, since=12)
      call s%field('dy', d%dy, d%n, since=12)
      call s%field('uaxial', d%uaxial, d%n, since=12)
      call s%field('fa', d%fa, d%n, since=12)
      call s%field('fs', d%fs, d%n, since=12)
      call s%field('fjs', d%fjs, d%n, since=12)
      call s%field('fjn', d%fjn, d%n, since=12)
   end subroutine walk_reinf

   subroutine walk_cable_nodes(s, d)
      type(stream_t), intent(inout) :: s
      type(cable_node_list_t), intent(inout) :: d
      call s%attr('n', d%n, since=12)
      call s%field('cable', d%cable, d%n, since=12)
      call s%field('block', d%block, d%n, since=12)
      call s%field('zone', d%zone, d%n, since=12)
      call s%field('matg', d%matg, d%n, since=12)
      call s%field('w1', d%w1, d%n, since=12)
      call s%field('w2', d%w2, d%n, since=12)
      call s%field('w3', d%w3, d%n, since=12)
      call s%field('x', d%x, d%n, since=12)
      call s%field('y', d%y, d%n, since=12)
      call s%field('hx', d%hx, d%n, since=12)
      call s%field('hy', d%hy, d%n, since=12)
      call s%field('vs', d%vs, d%n, since=12)
      call s%field('vx', d%vx, d%n, since=12)
      call s%field('vy', d%vy, d%n, since=12)
      call s%field('fx', d%fx, d%n, since=12)
      call s%field('fy', d%fy, d%n, since=12)
      call s%field('fg', d%fg, d%n, since=12)
      call s%field('slip', d%slip, d%n, since=12)
      call s%field('glen', d%glen, d%n, since=12)
      call s%field('mass', d%mass, d%n, since=12)
   end subroutine walk_cable_nodes

   subroutine walk_cable_elements(s, d)
      type(stream_t), intent(inout) :: s
      type(cable_element_list_t), intent(inout) :: d
      call s%attr('n', d%n, since=12)
      call s%field('cable', d%cable, d%n, since=12)
      call s%field('n1', d%n1, d%n, since=12)
      call s%field('n2', d%n2, d%n, since=12)
      call s%field('mats', d%mats, d%n, since=12)
      call s%field('area', d%area, d%n, since=12)
      call s%field('length0', d%length0, d%n, since=12)
      call s%field('length', d%length, d%n, since=12)
      call s%field('axial', d%axial, d%n, since=12)
      call s%field('pre', d%pre, d%n, since=12)
   end subroutine walk_cable_elements

   subroutine walk_ffield(s, f)
      type(stream_t), intent(inout) :: s
      type(ffield_t), intent(inout) :: f
      integer(ip) :: nz
      call s%attr('on', f%on, since=11)
      call s%attr('np', f%np, since=11)
      call s%attr('yl', f%yl, since=11)
      call s%attr('yu', f%yu, since=11)
      call s%attr('dy', f%dy, since=11)
      call s%attr('base_code', f%base_code, since=11)
      call s%attr('base_visc_x', f%base_visc(1), since=11)
      call s%attr('base_visc_y', f%base_visc(2), since=11)
      call s%attr('base_v', f%base_v, since=11)
      call s%attr('base_s', f%base_s, since=11)
      call s%attr('base_f', f%base_f, since=11)
      call s%attr('base_h', f%base_h, since=11)
      call s%attr('base_freq', f%base_freq, since=11)
      call s%attr('base_tload', f%base_tload, since=11)
      call s%field('vx', f%vx, f%np, since=11)
      call s%field('vy', f%vy, f%np, since=11)
      call s%field('ux', f%ux, f%np, since=11)
      call s%field('uy', f%uy, f%np, since=11)
      call s%field('fx', f%fx, f%np, since=11)
      call s%field('fy', f%fy, f%np, since=11)
      nz = max(0_ip, f%np - 1)
      call s%field('mat', f%mat, nz, since=11)
      call s%field('cons', f%cons, nz, since=11)
      call s%field('sxx0', f%sxx0, nz, since=11)
      call s%field('sxy0', f%sxy0, nz, since=11)
      call s%begin_group('zones')
      call walk_zones(s, f%zn)
      call s%end_group()
   end subroutine walk_ffield

   subroutine walk_thermal(s, t)
      type(stream_t), intent(inout) :: s
      type(thermal_t), intent(inout) :: t
      call s%attr('time', t%time, since=9)
      call s%attr('nsteps', t%nsteps, since=9)
      call s%attr('dt_user', t%dt_user, since=9)
      call s%attr('age', t%age, since=9)
      call s%attr('age_test', t%age_test, since=9)
      call s%attr('temp_limit', t%temp_limit, since=9)
      call s%attr('step_limit', t%step_limit, since=9)
      call s%attr('tol', t%tol, since=9)
      call s%attr('nther', t%nther, since=9)
      call s%attr('nmech', t%nmech, since=9)
      call s%attr('dt_last', t%dt_last, since=9)
      call s%attr('ng', t%ng, since=9)
      call s%field('temp', t%temp, t%ng, since=9)
      call s%field('fixed', t%fixed, t%ng, since=9)
      call s%field('dtacc', t%dtacc, t%ng, since=9)
      call s%attr('nc', t%nc, since=13)
      call s%field('ctemp', t%ctemp, t%nc, since=13)
      call s%field('cfixed', t%cfixed, t%nc, since=13)
      call s%field('cdtacc', t%cdtacc, t%nc, since=13)
      call s%attr('nb', t%nb, since=13)
      call s%field('btemp', t%btemp, t%nb, since=13)
      call s%field('bfixed', t%bfixed, t%nb, since=13)
      call s%field('bdtacc', t%bdtacc, t%nb, since=13)
      call s%attr('nrec', t%nrec, since=9)
      call s%attr('nset', t%nset, since=9)
      call s%field('rec_kind', t%rec_kind, t%nrec, since=9)
      call s%field('rec_id', t%rec_id, t%nrec, since=9)
      call s%field('rec_p1', t%rec_p1, t%nrec, since=9)
      call s%field('rec_p2', t%rec_p2, t%nrec, since=9)
      call s%field('rec_t0', t%rec_t0, t%nrec, since=9)
      call s%field('rec_set', t%rec_set, t%nrec, since=9)
      call s%attr('nthis', t%nthis, since=9)
      call s%attr('ntcyc', t%ntcyc, since=9)
      call s%attr('this_type', t%this_type, since=9)
      call s%field('this_gp', t%this_gp, t%nthis, since=9)
      call s%field('this_x', t%this_x, t%nthis, since=9)
      call s%field('this_y', t%this_y, t%nthis, since=9)
      if (s%mode == stream_write .and. .not. allocated(t%this_kind)) &
         allocate (t%this_kind(max(t%nthis, 0_ip)), source=0_ip)
      call s%field('this_kind', t%this_kind, t%nthis, since=13)
      call s%attr('nsamp', t%nsamp, since=9)
      call s%field('samp_time', t%samp_time, t%nsamp, since=9)
      call s%field('samp_val', t%samp_val, t%nsamp*max_thist, since=9)
   end subroutine walk_thermal

   !> Structural elements (model_structures).
   subroutine walk_structures(s, t)
      type(stream_t), intent(inout) :: s
      type(structure_t), intent(inout) :: t
      call s%begin_group('nodes')
      call walk_structure_nodes(s, t%nodes)
      call s%end_group()
      call s%begin_group('elements')
      call walk_structure_elements(s, t%elements)
      call s%end_group()
      call s%begin_group('interfaces')
      call walk_structure_interfaces(s, t%interfaces)
      call s%end_group()
   end subroutine walk_structures

   subroutine walk_structure_nodes(s, d)
      type(stream_t), intent(inout) :: s
      type(structure_node_list_t), intent(inout) :: d
      call s%attr('n', d%n, since=8)
      call s%field('x', d%x, d%n, since=8)
      call s%field('y', d%y, d%n, since=8)
      call s%field('vx', d%vx, d%n, since=8)
      call s%field('vy', d%vy, d%n, since=8)
      call s%field('vr', d%vr, d%n, since=8)
      call s%field('ux', d%ux, d%n, since=8)
      call s%field('uy', d%uy, d%n, since=8)
      call s%field('rot', d%rot, d%n, since=8)
      call s%field('fx', d%fx, d%n, since=8)
      call s%field('fy', d%fy, d%n, since=8)
      call s%field('fm', d%fm, d%n, since=8)
      call s%field('mass', d%mass, d%n, since=8)
      call s%field('inertia', d%inertia, d%n, since=8)
      call s%field('lx', d%lx, d%n, since=8)
      call s%field('ly', d%ly, d%n, since=8)
      call s%field('fix', d%fix, d%n, since=8)
      call s%field('material', d%material, d%n, since=8)
   end subroutine walk_structure_nodes

   subroutine walk_structure_elements(s, d)
      type(stream_t), intent(inout) :: s
      type(structure_element_list_t), intent(inout) :: d
      call s%attr('n', d%n, since=8)
      call s%field('n1', d%n1, d%n, since=8)
      call s%field('n2', d%n2, d%n, since=8)
      call s%field('material', d%material, d%n, since=8)
      call s%field('thick', d%thick, d%n, since=8)
      call s%field('length0', d%length0, d%n, since=8)
      call s%field('angle0', d%angle0, d%n, since=8)
      call s%field('young', d%young, d%n, since=8)
      call s%field('area', d%area, d%n, since=8)
      call s%field('inertia', d%inertia, d%n, since=8)
      call s%field('axial', d%axial, d%n, since=8)
      call s%field('shear', d%shear, d%n, since=8)
      call s%field('m1', d%m1, d%n, since=8)
      call s%field('m2', d%m2, d%n, since=8)
   end subroutine walk_structure_elements

   subroutine walk_structure_interfaces(s, d)
      type(stream_t), intent(inout) :: s
      type(structure_interface_list_t), intent(inout) :: d
      call s%attr('n', d%n, since=8)
      call s%field('node', d%node, d%n, since=8)
      call s%field('block', d%block, d%n, since=8)
      call s%field('edge', d%edge, d%n, since=8)
      call s%field('material', d%material, d%n, since=8)
      call s%field('x', d%x, d%n, since=8)
      call s%field('y', d%y, d%n, since=8)
      call s%field('nx', d%nx, d%n, since=8)
      call s%field('ny', d%ny, d%n, since=8)
      call s%field('un', d%un, d%n, since=8)
      call s%field('us', d%us, d%n, since=8)
      call s%field('fn', d%fn, d%n, since=8)
      call s%field('fs', d%fs, d%n, since=8)
      call s%field('flags', d%flags, d%n, since=8)
   end subroutine walk_structure_interfaces

   subroutine walk_fluid(s, f)
      type(stream_t), intent(inout) :: s
      type(fluid_t), intent(inout) :: f
      call s%attr('rhow', f%rhow, since=7)
      call s%attr('bulkw', f%bulkw, since=7)
      call s%attr('cohw', f%cohw, since=7)
      call s%attr('capratio', f%capratio, since=7)
      call s%attr('sflow', f%sflow, since=7)
      call s%attr('eff', f%eff, since=7)
      call s%attr('ywtab', f%ywtab, since=7)
      call s%attr('ptol', f%ptol, since=7)
      call s%attr('nd', f%nd, since=7)
      call s%field('p', f%p, f%nd, since=7)
      call s%field('fixed', f%fixed, f%nd, since=7)
      call s%field('vol', f%vol, f%nd, since=7)
      call s%field('xd', f%xd, f%nd, since=7)
      call s%field('yd', f%yd, f%nd, since=7)
      call s%attr('nc', f%nc, since=7)
      call s%field('aperture', f%aperture, f%nc, since=7)
      call s%field('q', f%q, f%nc, since=7)
      call s%field('bnd_code', f%bnd_code, f%nc, since=7)
      call s%field('bnd_p', f%bnd_p, f%nc, since=7)
      call s%field('bnd_g', f%bnd_g, f%nc, since=7)
      call s%field('cdom1', f%cdom1, f%nc, since=7)
      call s%field('cdom2', f%cdom2, f%nc, since=7)
   end subroutine walk_fluid

   !> The BE settings and link; the matrix is rebuilt at the next CYCLE.
   subroutine walk_be(s, b)
      type(stream_t), intent(inout) :: s
      type(be_t), intent(inout) :: b
      call s%attr('mat', b%mat, since=6)
      call s%attr('half', b%half, since=6)
      call s%attr('fix', b%fix, since=6)
      call s%attr('xh', b%xh, since=6)
      call s%attr('yh', b%yh, since=6)
      call s%attr('xv', b%xv, since=6)
      call s%attr('yv', b%yv, since=6)
      call s%attr('nc', b%nc, since=6)
      call s%attr('ne', b%ne, since=6)
      call s%field('corner', b%corner, b%nc, since=6)
      call s%field('ea', b%ea, b%ne, since=6)
      call s%field('eb', b%eb, b%ne, since=6)
      call s%attr('linked', b%linked, since=6)
      call s%attr('g', b%g, since=6)
      call s%attr('nu', b%nu, since=6)
      ! the positions at the link exist only after BE STIFFNESS
      call s%field('x0', b%x0, merge(b%nc, 0_ip, b%linked), since=6)
      call s%field('y0', b%y0, merge(b%nc, 0_ip, b%linked), since=6)
   end subroutine walk_be

   subroutine walk_materials(s, t)
      type(stream_t), intent(inout) :: s
      type(material_table_t), intent(inout) :: t
      call s%names('property_names', property_names)
      call s%attr('nmat', t%nmat)
      call s%field('value', t%value, t%nmat)
      call s%field('given', t%given, t%nmat)
   end subroutine walk_materials

   subroutine walk_geometry(s, g)
      type(stream_t), intent(inout) :: s
      type(geometry_t), intent(inout) :: g
      if (.not. s%mode_is_read()) call address_ensure(g)
      ! the records of the last synchronisation are not saved: start afresh
      if (s%mode_is_read()) call address_forget_rows(g)
      call s%attr('round', g%round)
      call s%attr('edge_min', g%edge_min)
      call s%attr('edge_set', g%edge_set)
      call s%attr('tol', g%tol)
      call s%attr('extent', g%extent)
      call s%attr('original_area', g%original_area)
      call s%attr('deleted_area', g%deleted_area)
      call s%attr('block_created', g%block_created)
      call s%attr('has_jregion', g%has_jregion)
      call s%attr('jregion_x', g%jregion_x)
      call s%attr('jregion_y', g%jregion_y)
      call s%attr('rng_state', g%rng_state)
      call s%attr('jmat_default', g%jmat_default)
      call s%attr('jcons_default', g%jcons_default)
      call s%attr('contacts_valid', g%contacts_valid)
      call s%attr('domains_valid', g%domains_valid)
      call s%attr('outer_domain', g%outer_domain)
      ! up to schema 9 a single count 'refused_cuts' (no longer read)
      call s%attr('cut_stats', g%cut_stats, since=10)
      ! schema 16: the refused cuts already counted (block, reason, path ends)
      call s%attr('nrefused_keys', g%nrefused_keys, since=16)
      if (s%mode == stream_write .or. s%version >= 16) &
         call s%field('refused_keys', g%refused_keys, g%nrefused_keys)
      call s%attr('mechanical', g%mechanical)
      ! schema 11: 1989 addresses (model_address); older files get them afresh
      call s%attr('ia_mfree', g%ia%mfree, since=11)
      call s%attr('ia_outer', g%ia%outer, since=11)
      call s%attr('ia_njunk', g%ia%njunk, since=11)
      call s%field('ia_junk_addr', g%ia%junk_addr, g%ia%njunk, since=11)
      call s%field('ia_junk_len', g%ia%junk_len, g%ia%njunk, since=11)
      call s%begin_group('blocks')
      call walk_blocks(s, g%blocks)
      call s%end_group()
      call s%begin_group('corners')
      call walk_corners(s, g%corners)
      call s%end_group()
      call s%begin_group('contacts')
      call walk_contacts(s, g%contacts)
      call s%end_group()
      call s%begin_group('domains')
      call walk_domains(s, g%domains)
      call s%end_group()
      call s%begin_group('pending')
      call walk_pending(s, g%pending)
      call s%end_group()
      call s%begin_group('tunnels')
      call walk_tunnels(s, g%tunnels)
      call s%end_group()
      call s%begin_group('jplot')
      call walk_jplot(s, g%jplot)
      call s%end_group()
      ! schema 2: fully-deformable blocks
      if (.not. (s%mode_is_read() .and. s%version < 2)) then
         call s%begin_group('gridpoints')
         call walk_gridpoints(s, g%gridpoints)
         call s%end_group()
         call s%begin_group('zones')
         call walk_zones(s, g%zones)
         call s%end_group()
      end if
   end subroutine walk_geometry

   subroutine walk_gridpoints(s, g)
      type(stream_t), intent(inout) :: s
      type(gridpoint_list_t), intent(inout) :: g
      call s%attr('n', g%n)
      call s%field('live', g%live, g%n)
      call s%field('block', g%block, g%n)
      call s%field('corner', g%corner, g%n)
      call s%field('x', g%x, g%n)
      call s%field('y', g%y, g%n)
      call s%field('vx', g%vx, g%n)
      call s%field('vy', g%vy, g%n)
      call s%field('ux', g%ux, g%n)
      call s%field('uy', g%uy, g%n)
      call s%field('fx', g%fx, g%n)
      call s%field('fy', g%fy, g%n)
      call s%field('mass', g%mass, g%n)
      call s%field('vfix', g%vfix, g%n)
      call s%field('addr', g%addr, g%n, since=11)
   end subroutine walk_gridpoints

   subroutine walk_zones(s, z)
      type(stream_t), intent(inout) :: s
      type(zone_list_t), intent(inout) :: z
      call s%attr('n', z%n)
      call s%field('live', z%live, z%n)
      call s%field('block', z%block, z%n)
      call s%field('g1', z%g1, z%n)
      call s%field('g2', z%g2, z%n)
      call s%field('g3', z%g3, z%n)
      call s%field('sxx', z%sxx, z%n)
      call s%field('sxy', z%sxy, z%n)
      call s%field('syy', z%syy, z%n)
      call s%field('szz', z%szz, z%n)
      call s%field('state', z%state, z%n)
      call s%field('addr', z%addr, z%n, since=11)
   end subroutine walk_zones

   subroutine walk_blocks(s, b)
      type(stream_t), intent(inout) :: s
      type(block_list_t), intent(inout) :: b
      logical :: sd
      call s%attr('n', b%n)
      call s%field('live', b%live, b%n)
      call s%field('first_corner', b%first_corner, b%n)
      call s%field('ncorner', b%ncorner, b%n)
      call s%field('material', b%material, b%n)
      call s%field('cons', b%cons, b%n)
      call s%field('area', b%area, b%n)
      call s%field('xc', b%xc, b%n)
      call s%field('yc', b%yc, b%n)
      call s%field('xmin', b%xmin, b%n)
      call s%field('xmax', b%xmax, b%n)
      call s%field('ymin', b%ymin, b%n)
      call s%field('ymax', b%ymax, b%n)
      call s%field('mass', b%mass, b%n)
      call s%field('inertia', b%inertia, b%n)
      call s%field('vx', b%vx, b%n)
      call s%field('vy', b%vy, b%n)
      call s%field('vr', b%vr, b%n)
      call s%field('ux', b%ux, b%n)
      call s%field('uy', b%uy, b%n)
      call s%field('rot', b%rot, b%n)
      call s%field('fx', b%fx, b%n)
      call s%field('fy', b%fy, b%n)
      call s%field('fm', b%fm, b%n)
      call s%field('lx', b%lx, b%n)
      call s%field('ly', b%ly, b%n)
      call s%field('fixed', b%fixed, b%n)
      call s%field('fdef', b%fdef, b%n, since=2)
      call s%field('zfirst', b%zfirst, b%n, since=2)
      call s%field('nzone', b%nzone, b%n, since=2)
      call s%field('gfirst', b%gfirst, b%n, since=2)
      call s%field('ngp', b%ngp, b%n, since=2)
      call s%field('addr', b%addr, b%n, since=11)
      call s%field('sdef', b%sdef, b%n, since=12)
      ! a model without SDEF blocks leaves their twelve reals out
      ! (block_sdef_fields); the file has them all the same (zeros), so files
      ! keep their layout: made for the write, dropped after it
      sd = s%mode_is_read() .or. allocated(b%exx)
      if (.not. sd) call block_sdef_fields(b)
      call s%field('exx', b%exx, b%n, since=12)
      call s%field('eyy', b%eyy, b%n, since=12)
      call s%field('exy', b%exy, b%n, since=12)
      call s%field('dxx', b%dxx, b%n, since=12)
      call s%field('dyy', b%dyy, b%n, since=12)
      call s%field('dxy', b%dxy, b%n, since=12)
      call s%field('sxx', b%sxx, b%n, since=12)
      call s%field('syy', b%syy, b%n, since=12)
      call s%field('sxy', b%sxy, b%n, since=12)
      call s%field('qxx', b%qxx, b%n, since=12)
      call s%field('qyy', b%qyy, b%n, since=12)
      call s%field('qxy', b%qxy, b%n, since=12)
      if (.not. sd) call drop_sdef_fields(b)
      ! read back with no SDEF block and all zero: what a left-out field stands for
      if (s%mode_is_read() .and. .not. s%failed() .and. allocated(b%exx) .and. allocated(b%sdef)) then
         ! (a damaged file, sdef shorter than n, is left to the reader to report)
         if (size(b%sdef, kind=ip) >= b%n) then
            if (.not. any(b%sdef(1:b%n)) .and. all(b%exx == 0.0_wp) .and. all(b%eyy == 0.0_wp) .and. &
                all(b%exy == 0.0_wp) .and. all(b%dxx == 0.0_wp) .and. all(b%dyy == 0.0_wp) .and. &
                all(b%dxy == 0.0_wp) .and. all(b%sxx == 0.0_wp) .and. all(b%syy == 0.0_wp) .and. &
                all(b%sxy == 0.0_wp) .and. all(b%qxx == 0.0_wp) .and. all(b%qyy == 0.0_wp) .and. &
                all(b%qxy == 0.0_wp)) call drop_sdef_fields(b)
         end if
      end if
      call s%field('bstate', b%bstate, b%n, since=12)
   contains
      subroutine drop_sdef_fields(b)
         type(block_list_t), intent(inout) :: b
         if (allocated(b%exx)) deallocate (b%exx, b%eyy, b%exy, b%dxx, b%dyy, b%dxy, b%sxx, &
                                           b%syy, b%sxy, b%qxx, b%qyy, b%qxy)
      end subroutine drop_sdef_fields
   end subroutine walk_blocks

   subroutine walk_corners(s, c)
      type(stream_t), intent(inout) :: s
      type(corner_list_t), intent(inout) :: c
      call s%attr('n', c%n)
      call s%field('live', c%live, c%n)
      call s%field('x', c%x, c%n)
      call s%field('y', c%y, c%n)
      call s%field('block', c%block, c%n)
      call s%field('next', c%next, c%n)
      call s%field('prev', c%prev, c%n)
      call s%field('rx', c%rx, c%n)
      call s%field('ry', c%ry, c%n)
      call s%field('radius', c%radius, c%n)
      call s%field('ux', c%ux, c%n)
      call s%field('uy', c%uy, c%n)
      call s%field('gp', c%gp, c%n, since=2)
      call s%field('addr', c%addr, c%n, since=11)
   end subroutine walk_corners

   subroutine walk_contacts(s, c)
      type(stream_t), intent(inout) :: s
      type(contact_list_t), intent(inout) :: c
      logical :: jc3, has_ud
      call s%attr('n', c%n)
      call s%field('live', c%live, c%n)
      call s%field('block1', c%block1, c%n)
      call s%field('block2', c%block2, c%n)
      call s%field('kind', c%kind, c%n)
      call walk_contact_ends(s, c)
      call s%field('jmat', c%jmat, c%n)
      call s%field('jcons', c%jcons, c%n)
      call s%field('dom1', c%dom1, c%n)
      call s%field('dom2', c%dom2, c%n)
      call s%field('x', c%x, c%n)
      call s%field('y', c%y, c%n)
      call s%field('nx', c%nx, c%n)
      call s%field('ny', c%ny, c%n)
      call s%field('length', c%length, c%n)
      call s%field('gap', c%gap, c%n)
      ! a model without JCONS 3 contacts leaves their three fields out
      ! (joint_state_jcons3); the file has them all the same (zeros), so
      ! files keep their layout: made for the write, dropped after it
      ! (and ud without a dilating law: joint_state_ud, the same way)
      jc3 = s%mode_is_read() .or. allocated(c%state%phi_eff)
      if (.not. jc3) call joint_state_jcons3(c)
      has_ud = s%mode_is_read() .or. allocated(c%state%ud)
      if (.not. has_ud) call joint_state_ud(c)
      call s%begin_group('state')
      call walk_joint_state(s, c%state, c%n)
      call s%end_group()
      if (.not. jc3) deallocate (c%state%phi_eff, c%state%reversal, c%state%dus_old)
      if (.not. has_ud) deallocate (c%state%ud)
      if (s%mode_is_read() .and. allocated(c%state%ud)) then
         if (all(c%state%ud == 0.0_wp)) deallocate (c%state%ud)
      end if
      ! read back all zero, they are what a left-out field stands for
      if (s%mode_is_read() .and. allocated(c%state%phi_eff) .and. allocated(c%state%reversal) .and. &
          allocated(c%state%dus_old)) then
         if (all(c%state%phi_eff == 0.0_wp) .and. all(c%state%reversal == 0.0_wp) .and. &
             all(c%state%dus_old == 0.0_wp)) deallocate (c%state%phi_eff, c%state%reversal, c%state%dus_old)
      end if
      call s%field('addr', c%addr, c%n, since=11)
   end subroutine walk_contacts

   !> A contact's two feature ids (end1, end2) as the file keeps them: four
   !> lists corner1, corner2, edge1, edge2, 0 where the kind has none (so
   !> files keep their layout and capacities); read back, each end is the
   !> list its kind names.
   subroutine walk_contact_ends(s, c)
      type(stream_t), intent(inout) :: s
      type(contact_list_t), intent(inout) :: c
      integer(ip), allocatable :: c1(:), c2(:), e1(:), e2(:)
      integer(ip) :: i
      if (.not. s%mode_is_read() .and. allocated(c%end1)) then
         i = size(c%end1)
         allocate (c1(i), c2(i), e1(i), e2(i), source=0_ip)
         do i = 1, c%n
            c1(i) = contact_corner1(c, i)
            c2(i) = contact_corner2(c, i)
            e1(i) = contact_edge1(c, i)
            e2(i) = contact_edge2(c, i)
         end do
      end if
      call s%field('corner1', c1, c%n)
      call s%field('corner2', c2, c%n)
      call s%field('edge1', e1, c%n)
      call s%field('edge2', e2, c%n)
      if (.not. s%mode_is_read()) return
      if (allocated(c%end1)) deallocate (c%end1)
      if (allocated(c%end2)) deallocate (c%end2)
      if (.not. (allocated(c1) .and. allocated(c2) .and. allocated(e1) .and. allocated(e2) &
                 .and. allocated(c%kind))) return
      allocate (c%end1(size(c1)), c%end2(size(c1)), source=0_ip)
      do i = 1, min(size(c1), size(c%kind))
         c%end1(i) = merge(e1(i), c1(i), c%kind(i) == 3)
         c%end2(i) = merge(e2(i), c2(i), c%kind(i) == 2)
      end do
   end subroutine walk_contact_ends

   !> Joint state: indexed like the contacts, `n` entries.
   subroutine walk_joint_state(s, j, n)
      type(stream_t), intent(inout) :: s
      type(joint_state_t), intent(inout) :: j
      integer(ip), intent(in) :: n
      call s%field('fn', j%fn, n)
      call s%field('fs', j%fs, n)
      call s%field('un', j%un, n)
      call s%field('us', j%us, n)
      call s%field('flags', j%flags, n)
      call s%field('ud', j%ud, n, since=14)
      call s%field('phi_eff', j%phi_eff, n)
      call s%field('reversal', j%reversal, n)
      call s%field('dus_old', j%dus_old, n)
   end subroutine walk_joint_state

   subroutine walk_domains(s, d)
      type(stream_t), intent(inout) :: s
      type(domain_list_t), intent(inout) :: d
      call s%attr('n', d%n)
      call s%field('live', d%live, d%n)
      call s%field('outer', d%outer, d%n)
      call s%field('area', d%area, d%n)
      call s%field('first', d%first, d%n)
      call s%field('count', d%count, d%n)
      call s%attr('nring', d%nring)
      call s%field('ring', d%ring, d%nring)
      call s%field('addr', d%addr, d%n, since=11)
   end subroutine walk_domains

   subroutine walk_pending(s, p)
      type(stream_t), intent(inout) :: s
      type(pending_list_t), intent(inout) :: p
      call s%attr('n', p%n)
      call s%field('x1', p%x1, p%n)
      call s%field('y1', p%y1, p%n)
      call s%field('x2', p%x2, p%n)
      call s%field('y2', p%y2, p%n)
   end subroutine walk_pending

   subroutine walk_tunnels(s, t)
      type(stream_t), intent(inout) :: s
      type(tunnel_list_t), intent(inout) :: t
      call s%attr('n', t%n)
      call s%field('xc', t%xc, t%n)
      call s%field('yc', t%yc, t%n)
      call s%field('r', t%r, t%n)
      call s%field('nside', t%nside, t%n)
   end subroutine walk_tunnels

   subroutine walk_jplot(s, j)
      type(stream_t), intent(inout) :: s
      type(jplot_list_t), intent(inout) :: j
      call s%attr('on', j%on)
      call s%attr('n', j%n)
      call s%field('x1', j%x1, j%n)
      call s%field('y1', j%y1, j%n)
      call s%field('x2', j%x2, j%n)
      call s%field('y2', j%y2, j%n)
      call s%field('block', j%block, j%n)
   end subroutine walk_jplot

   subroutine walk_mechanics(s, m)
      type(stream_t), intent(inout) :: s
      type(mechanics_t), intent(inout) :: m
      call s%attr('time', m%time)
      call s%attr('step', m%step)
      call s%attr('dt', m%dt)
      call s%attr('frac_block', m%frac_block)
      call s%attr('frac_zone', m%frac_zone)
      call s%attr('frac_fluid', m%frac_fluid)
      call s%attr('damping', m%damping)
      call s%attr('auto_fac', m%auto_fac)
      call s%attr('auto_mult1', m%auto_mult1)
      call s%attr('auto_mult2', m%auto_mult2)
      call s%attr('auto_alpha', m%auto_alpha)
      call s%attr('local_alpha', m%local_alpha, since=15)
      call s%attr('kinetic_old', m%kinetic_old)
      call s%attr('rayleigh_fcrit', m%rayleigh_fcrit)
      call s%attr('rayleigh_freq', m%rayleigh_freq)
      call s%attr('rayleigh_mass', m%rayleigh_mass)
      call s%attr('rayleigh_stiff', m%rayleigh_stiff)
      call s%attr('internal_fcrit', m%internal_fcrit, since=12)
      call s%attr('internal_freq', m%internal_freq, since=12)
      call s%attr('internal_mass', m%internal_mass, since=12)
      call s%attr('internal_stiff', m%internal_stiff, since=12)
      call s%attr('mscale', m%mscale)
      call s%attr('mscale_zone', m%mscale_zone)
      call s%attr('mscale_block', m%mscale_block)
      call s%attr('mscale_part', m%mscale_part, since=2)
      call s%attr('mscale_tdel', m%mscale_tdel, since=2)
      call s%attr('nupcon', m%nupcon)
      call s%attr('dscan', m%dscan)
      call s%attr('cscan', m%cscan)
      call s%attr('ovtol', m%ovtol)
      call s%attr('clemin', m%clemin)
      call s%attr('clemin_auto', m%clemin_auto)
      call s%attr('motion_since_scan', m%motion_since_scan)
      call s%attr('unbalanced', m%unbalanced)
      call s%attr('masses_valid', m%masses_valid)
      call s%attr('fxhis', m%fxhis, since=5)
      call s%attr('fyhis', m%fyhis, since=5)
      call s%attr('search_current', m%search_current, since=17)
      call s%attr('search_sizes', m%search_sizes, since=17)
      call s%attr('search_margin', m%search_margin, since=17)
      call s%attr('probe_time', m%probe_time, since=18)
      call s%attr('probe_w', m%probe_w, since=18)
      call s%attr('probe_wref', m%probe_wref, since=18)
   end subroutine walk_mechanics

   subroutine walk_boundary(s, b)
      type(stream_t), intent(inout) :: s
      type(boundary_t), intent(inout) :: b
      call s%attr('n', b%n)
      call s%attr('corners_seen', b%corners_seen)
      call s%attr('t_start', b%t_start)
      call s%field('corner', b%corner, b%n)
      call s%field('ix', b%ix, b%n)
      call s%field('iy', b%iy, b%n)
      call s%field('fx', b%fx, b%n)
      call s%field('fy', b%fy, b%n)
      call s%field('dfx', b%dfx, b%n)
      call s%field('dfy', b%dfy, b%n)
      call s%field('hx', b%hx, b%n)
      call s%field('hy', b%hy, b%n)
      call s%field('freqx', b%freqx, b%n)
      call s%field('tloadx', b%tloadx, b%n)
      call s%field('freqy', b%freqy, b%n)
      call s%field('tloady', b%tloady, b%n)
      call s%field('xmul', b%xmul, b%n)
      call s%field('ymul', b%ymul, b%n)
      call s%field('vx', b%vx, b%n)
      call s%field('vy', b%vy, b%n)
      call s%field('vis', b%vis, b%n, since=4)
      call s%field('vmat', b%vmat, b%n, since=4)
      call s%field('ff', b%ff, b%n, since=11)
      ! schema 10: SET FUP and the boundary stresses kept as tractions (older
      ! files: FUP, the default, and no tractions; their stresses were saved
      ! as the fixed forces fx, fy and stay so)
      call s%attr('fup', b%fup, since=10)
      call s%field('sxx_prev', b%sxx_prev, b%n, since=10)
      call s%field('sxy_prev', b%sxy_prev, b%n, since=10)
      call s%field('syy_prev', b%syy_prev, b%n, since=10)
      call s%field('sxx_next', b%sxx_next, b%n, since=10)
      call s%field('sxy_next', b%sxy_next, b%n, since=10)
      call s%field('syy_next', b%syy_next, b%n, since=10)
      call s%field('dsxx_prev', b%dsxx_prev, b%n, since=10)
      call s%field('dsxy_prev', b%dsxy_prev, b%n, since=10)
      call s%field('dsyy_prev', b%dsyy_prev, b%n, since=10)
      call s%field('dsxx_next', b%dsxx_next, b%n, since=10)
      call s%field('dsxy_next', b%dsxy_next, b%n, since=10)
      call s%field('dsyy_next', b%dsyy_next, b%n, since=10)
      call s%field('end_prev', b%end_prev, b%n, since=10)
      call s%field('end_next', b%end_next, b%n, since=10)
      call s%begin_group('table1')
      call walk_boundary_table(s, b%table(1))
      call s%end_group()
      call s%begin_group('table2')
      call walk_boundary_table(s, b%table(2))
      call s%end_group()
      ! schema 3: SET ZPRESS sources
      if (.not. (s%mode_is_read() .and. s%version < 3)) then
         call s%begin_group('zpress')
         call walk_zpress(s, b%zp)
         call s%end_group()
      end if
   end subroutine walk_boundary

   subroutine walk_zpress(s, z)
      type(stream_t), intent(inout) :: s
      type(zpress_t), intent(inout) :: z
      call s%attr('n', z%n, since=3)
      call s%attr('h_next', z%h_next, since=3)
      call s%attr('freq_next', z%freq_next, since=3)
      call s%attr('tload_next', z%tload_next, since=3)
      call s%field('x', z%x, z%n, since=3)
      call s%field('y', z%y, z%n, since=3)
      call s%field('rad', z%rad, z%n, since=3)
      call s%field('pz', z%pz, z%n, since=3)
      call s%field('h', z%h, z%n, since=3)
      call s%field('freq', z%freq, z%n, since=3)
      call s%field('tload', z%tload, z%n, since=3)
      call s%field('nzone', z%nzone, z%n, since=3)
      call s%attr('nz', z%nz, since=3)
      call s%field('zone', z%zone, z%nz, since=3)
      call s%field('src', z%src, z%nz, since=3)
   end subroutine walk_zpress

   subroutine walk_boundary_table(s, t)
      type(stream_t), intent(inout) :: s
      type(boundary_table_t), intent(inout) :: t
      call s%text('heading', t%heading)
      call s%attr('np', t%np)
      call s%attr('dt', t%dt)
      call s%field('values', t%values, t%np)
   end subroutine walk_boundary_table

   subroutine walk_history(s, h)
      type(stream_t), intent(inout) :: s
      type(history_t), intent(inout) :: h
      call s%names('kind_names', hist_names)
      call s%attr('n', h%n)
      call s%field('kind', h%kind, h%n)
      call s%field('entity', h%entity, h%n)
      call s%field('x', h%x, h%n)
      call s%field('y', h%y, h%n)
      call s%field('px', h%px, h%n)
      call s%field('py', h%py, h%n)
      call s%attr('ncyc', h%ncyc)
      call s%attr('typed', h%typed)
      call s%attr('nsample', h%nsample)
      call s%field('time', h%time, h%nsample)
      call s%field('step', h%step, h%nsample)
      call s%field('values', h%values, h%nsample)
      call s%field('first_sample', h%first_sample, h%n, since=4)
   end subroutine walk_history

end module io_schema
