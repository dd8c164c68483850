!> SAVE / RESTART round trip (io_schema): a model with a distinct value in
!> every field comes back from its save file identical, field by field and
!> bit for bit, with the same array capacities; list growth still works
!> after a restart. Reference: the model before saving; tolerance: none
!> (reals compared as bit patterns).
!>
!> Guard against unsaved new fields: the mirror types below copy the field
!> declarations of the model types; if a type gains a field its size no
!> longer matches its mirror and this test fails. Then: add the field to
!> io_schema's walker, to tests/lib/testing_model.f90 (filler and
!> comparison) and to the mirror here.
program test_save_restart
   use core_kinds, only: wp, ip, i8
   use core_error, only: error_t
   use model_state, only: model_t, model_reset
   use model_tables, only: table_set_t
   use model_reinforcement, only: reinforcement_t
   use model_materials, only: material_table_t
   use model_geometry, only: geometry_t, block_list_t, corner_list_t, contact_list_t, &
                             joint_state_t, domain_list_t, pending_list_t, tunnel_list_t, &
                             jplot_list_t, geometry_add_contact, ia_state_t
   use geometry_blocks, only: geometry_add_block
   use model_zones, only: gridpoint_list_t, zone_list_t
   use model_mechanics, only: mechanics_t
   use model_history, only: history_t
   use model_boundary, only: boundary_t, boundary_table_t, zpress_t
   use model_be, only: be_t
   use model_structures, only: structure_t, structure_node_list_t, structure_element_list_t, &
                               structure_interface_list_t
   use model_fluid, only: fluid_t
   use model_thermal, only: thermal_t
   use model_ffield, only: ffield_t
   use io_schema, only: io_save_model, io_load_model
   use io_posix, only: posix_unlink
   use io_hdf5_stream, only: stream_t
   use testing, only: check, check_equal, testing_finish
   use testing_model, only: fill_model, compare_models
   implicit none

   type :: gridpoint_list_mirror
      integer(ip) :: n = 0
      logical, allocatable :: live(:)
      integer(ip), allocatable :: block(:), corner(:)
      real(wp), allocatable :: x(:), y(:), vx(:), vy(:), ux(:), uy(:), fx(:), fy(:), mass(:)
      integer, allocatable :: vfix(:)
      integer(ip), allocatable :: addr(:)
   end type gridpoint_list_mirror

   type :: zone_list_mirror
      integer(ip) :: n = 0
      logical, allocatable :: live(:)
      integer(ip), allocatable :: block(:), g1(:), g2(:), g3(:)
      real(wp), allocatable :: sxx(:), sxy(:), syy(:), szz(:)
      integer, allocatable :: state(:)
      integer(ip), allocatable :: addr(:)
   end type zone_list_mirror

   type :: block_list_mirror
      integer(ip) :: n = 0
      logical, allocatable :: live(:)
      integer(ip), allocatable :: first_corner(:), ncorner(:)
      integer(ip), allocatable :: material(:), cons(:)
      real(wp), allocatable :: area(:), xc(:), yc(:)
      real(wp), allocatable :: xmin(:), xmax(:), ymin(:), ymax(:)
      real(wp), allocatable :: mass(:), inertia(:)
      real(wp), allocatable :: vx(:), vy(:), vr(:)
      real(wp), allocatable :: ux(:), uy(:), rot(:)
      real(wp), allocatable :: fx(:), fy(:), fm(:)
      real(wp), allocatable :: lx(:), ly(:)
      logical, allocatable :: fixed(:)
      logical, allocatable :: fdef(:)
      integer(ip), allocatable :: zfirst(:), nzone(:), gfirst(:), ngp(:)
      integer(ip), allocatable :: addr(:)
      logical, allocatable :: sdef(:)
      real(wp), allocatable :: exx(:), eyy(:), exy(:), dxx(:), dyy(:), dxy(:)
      real(wp), allocatable :: sxx(:), syy(:), sxy(:), qxx(:), qyy(:), qxy(:)
      integer(ip), allocatable :: bstate(:)
   end type block_list_mirror

   type :: corner_list_mirror
      integer(ip) :: n = 0
      logical, allocatable :: live(:)
      real(wp), allocatable :: x(:), y(:)
      integer(ip), allocatable :: block(:), next(:), prev(:)
      real(wp), allocatable :: rx(:), ry(:), radius(:)
      real(wp), allocatable :: ux(:), uy(:)
      integer(ip), allocatable :: gp(:)
      integer(ip), allocatable :: addr(:)
   end type corner_list_mirror

   type :: joint_state_mirror
      real(wp), allocatable :: fn(:), fs(:)
      real(wp), allocatable :: un(:), us(:)
      integer, allocatable :: flags(:)
      real(wp), allocatable :: ud(:)
      real(wp), allocatable :: phi_eff(:)
      real(wp), allocatable :: reversal(:)
      real(wp), allocatable :: dus_old(:)
   end type joint_state_mirror

   type :: contact_list_mirror
      integer(ip) :: n = 0
      logical, allocatable :: live(:)
      integer(ip), allocatable :: block1(:), block2(:), kind(:)
      integer(ip), allocatable :: end1(:), end2(:)
      integer(ip), allocatable :: jmat(:), jcons(:), dom1(:), dom2(:)
      real(wp), allocatable :: x(:), y(:), nx(:), ny(:), length(:)
      real(wp), allocatable :: gap(:)
      type(joint_state_mirror) :: state
      integer(ip), allocatable :: addr(:)
   end type contact_list_mirror

   type :: domain_list_mirror
      integer(ip) :: n = 0
      logical, allocatable :: live(:), outer(:)
      real(wp), allocatable :: area(:)
      integer(ip), allocatable :: first(:), count(:)
      integer(ip) :: nring = 0
      integer(ip), allocatable :: ring(:)
      integer(ip), allocatable :: addr(:)
   end type domain_list_mirror

   type :: pending_list_mirror
      integer(ip) :: n = 0
      real(wp), allocatable :: x1(:), y1(:), x2(:), y2(:)
   end type pending_list_mirror

   type :: tunnel_list_mirror
      integer(ip) :: n = 0
      real(wp), allocatable :: xc(:), yc(:), r(:)
      integer(ip), allocatable :: nside(:)
   end type tunnel_list_mirror

   type :: jplot_list_mirror
      logical :: on = .false.
      integer(ip) :: n = 0
      real(wp), allocatable :: x1(:), y1(:), x2(:), y2(:)
      integer(ip), allocatable :: block(:)
   end type jplot_list_mirror

   type :: geometry_mirror
      type(block_list_t) :: blocks
      type(corner_list_t) :: corners
      type(contact_list_t) :: contacts
      type(domain_list_t) :: domains
      type(pending_list_t) :: pending
      type(tunnel_list_t) :: tunnels
      type(jplot_list_t) :: jplot
      type(gridpoint_list_t) :: gridpoints
      type(zone_list_t) :: zones
      type(ia_state_t) :: ia
      real(wp) :: round, edge_min
      logical :: edge_set
      real(wp) :: tol, extent, original_area, deleted_area
      logical :: block_created, has_jregion
      real(wp) :: jregion_x(4), jregion_y(4)
      integer(i8) :: rng_state
      integer(ip) :: jmat_default, jcons_default
      logical :: contacts_valid, domains_valid
      integer(ip) :: outer_domain
      integer(ip) :: cut_stats(9)
      real(wp), allocatable :: refused_keys(:, :)
      integer(ip) :: nrefused_keys
      logical :: mechanical
   end type geometry_mirror

   type :: mechanics_mirror
      real(wp) :: time
      integer(i8) :: step
      real(wp) :: dt, frac_block, frac_zone, frac_fluid
      integer :: damping
      real(wp) :: auto_fac, auto_mult1, auto_mult2, auto_alpha, probe_time, probe_w, probe_wref
      real(wp) :: local_alpha, kinetic_old
      real(wp) :: rayleigh_fcrit, rayleigh_freq
      logical :: rayleigh_mass, rayleigh_stiff
      real(wp) :: internal_fcrit, internal_freq
      logical :: internal_mass, internal_stiff, mscale
      real(wp) :: mscale_zone, mscale_block
      logical :: mscale_part
      real(wp) :: mscale_tdel
      integer(ip) :: nupcon, dscan, cscan
      real(wp) :: ovtol, clemin, clemin_auto, motion_since_scan, unbalanced
      logical :: masses_valid
      real(wp) :: fxhis, fyhis
      logical :: search_current
      integer(ip) :: search_sizes(3)
      real(wp) :: search_margin
   end type mechanics_mirror

   type :: history_mirror
      integer :: n
      integer, allocatable :: kind(:)
      integer(ip), allocatable :: entity(:)
      real(wp), allocatable :: x(:), y(:), px(:), py(:)
      integer(ip) :: ncyc
      integer :: typed
      integer(ip) :: nsample
      real(wp), allocatable :: time(:)
      integer(ip), allocatable :: step(:)
      real(wp), allocatable :: values(:, :)
      integer(ip), allocatable :: first_sample(:)
   end type history_mirror

   type :: material_table_mirror
      integer :: nmat
      real(wp), allocatable :: value(:, :)
      logical, allocatable :: given(:, :)
   end type material_table_mirror

   type :: boundary_table_mirror
      character(len=:), allocatable :: heading
      integer(ip) :: np
      real(wp) :: dt
      real(wp), allocatable :: values(:)
   end type boundary_table_mirror

   type :: zpress_mirror
      integer(ip) :: n
      integer :: h_next
      real(wp) :: freq_next, tload_next
      real(wp), allocatable :: x(:), y(:), rad(:), pz(:)
      integer, allocatable :: h(:)
      real(wp), allocatable :: freq(:), tload(:)
      integer(ip), allocatable :: nzone(:)
      integer(ip) :: nz
      integer(ip), allocatable :: zone(:), src(:)
   end type zpress_mirror

   type :: boundary_mirror
      integer(ip) :: n, corners_seen
      real(wp) :: t_start
      integer(ip), allocatable :: corner(:)
      integer, allocatable :: ix(:), iy(:)
      real(wp), allocatable :: fx(:), fy(:), dfx(:), dfy(:)
      integer, allocatable :: hx(:), hy(:)
      real(wp), allocatable :: freqx(:), tloadx(:), freqy(:), tloady(:)
      real(wp), allocatable :: xmul(:), ymul(:), vx(:), vy(:)
      integer, allocatable :: vis(:), vmat(:), ff(:)
      logical :: fup
      real(wp), allocatable :: sxx_prev(:), sxy_prev(:), syy_prev(:)
      real(wp), allocatable :: sxx_next(:), sxy_next(:), syy_next(:)
      real(wp), allocatable :: dsxx_prev(:), dsxy_prev(:), dsyy_prev(:)
      real(wp), allocatable :: dsxx_next(:), dsxy_next(:), dsyy_next(:)
      integer(ip), allocatable :: end_prev(:), end_next(:)
      type(boundary_table_t) :: table(2)
      type(zpress_t) :: zp
   end type boundary_mirror

   type :: be_mirror
      integer :: mat
      logical :: half, fix
      real(wp) :: xh, yh, xv, yv
      integer(ip) :: nc, ne
      integer(ip), allocatable :: corner(:), ea(:), eb(:)
      logical :: linked
      real(wp) :: g, nu
      real(wp), allocatable :: x0(:), y0(:)
      real(wp), allocatable :: kmat(:, :), u(:), f(:)   ! work, not saved
   end type be_mirror

   type :: structure_node_mirror
      integer(ip) :: n
      real(wp), allocatable :: x(:), y(:), vx(:), vy(:), vr(:), ux(:), uy(:), rot(:)
      real(wp), allocatable :: fx(:), fy(:), fm(:), mass(:), inertia(:), lx(:), ly(:)
      integer, allocatable :: fix(:)
      integer(ip), allocatable :: material(:)
   end type structure_node_mirror

   type :: structure_element_mirror
      integer(ip) :: n
      integer(ip), allocatable :: n1(:), n2(:), material(:)
      real(wp), allocatable :: thick(:), length0(:), angle0(:), young(:), area(:), inertia(:)
      real(wp), allocatable :: axial(:), shear(:), m1(:), m2(:)
   end type structure_element_mirror

   type :: structure_interface_mirror
      integer(ip) :: n
      integer(ip), allocatable :: node(:), block(:), edge(:), material(:)
      real(wp), allocatable :: x(:), y(:), nx(:), ny(:), un(:), us(:), fn(:), fs(:)
      integer, allocatable :: flags(:)
   end type structure_interface_mirror

   type :: structure_mirror
      type(structure_node_mirror) :: nodes
      type(structure_element_mirror) :: elements
      type(structure_interface_mirror) :: interfaces
   end type structure_mirror
   type :: fluid_mirror
      real(wp) :: rhow, bulkw, cohw, capratio
      logical :: sflow, eff
      real(wp) :: ywtab, ptol
      integer(ip) :: nd
      real(wp), allocatable :: p(:)
      logical, allocatable :: fixed(:)
      real(wp), allocatable :: vol(:), xd(:), yd(:)
      integer(ip) :: nc
      real(wp), allocatable :: aperture(:), q(:)
      integer(ip), allocatable :: bnd_code(:)
      real(wp), allocatable :: bnd_p(:), bnd_g(:)
      integer(ip), allocatable :: cdom1(:), cdom2(:)
   end type fluid_mirror
   type :: thermal_mirror
      real(wp) :: time
      integer(ip) :: nsteps
      real(wp) :: dt_user, age
      logical :: age_test
      real(wp) :: temp_limit
      integer(ip) :: step_limit
      real(wp) :: tol
      integer(ip) :: nther, nmech
      real(wp) :: dt_last
      integer(ip) :: ng
      real(wp), allocatable :: temp(:)
      logical, allocatable :: fixed(:)
      real(wp), allocatable :: dtacc(:)
      integer(ip) :: nc, nb
      real(wp), allocatable :: ctemp(:), cdtacc(:)
      logical, allocatable :: cfixed(:)
      real(wp), allocatable :: btemp(:), bdtacc(:)
      logical, allocatable :: bfixed(:)
      integer(ip) :: nrec
      integer(ip), allocatable :: rec_kind(:), rec_id(:)
      real(wp), allocatable :: rec_p1(:), rec_p2(:), rec_t0(:)
      integer(ip), allocatable :: rec_set(:)
      integer(ip) :: nset
      integer(ip) :: nthis, ntcyc, this_type
      integer(ip), allocatable :: this_gp(:), this_kind(:)
      real(wp), allocatable :: this_x(:), this_y(:)
      integer(ip) :: nsamp
      real(wp), allocatable :: samp_time(:), samp_val(:)
   end type thermal_mirror

   type :: model_mirror
      character(len=:), allocatable :: heading
      type(material_table_t) :: materials
      real(wp) :: gravity(2)
      type(geometry_t) :: geometry
      logical :: cycled
      type(mechanics_t) :: mech
      type(history_t) :: hist
      type(boundary_t) :: bound
      type(be_t) :: be
      type(structure_t), allocatable :: structures
      type(reinforcement_t), allocatable :: reinforcement
      type(fluid_t), allocatable :: fluid
      type(thermal_t), allocatable :: thermal
      type(ffield_t) :: ffield
      type(table_set_t) :: tables
   end type model_mirror

   type :: ffield_mirror
      logical :: on
      integer(ip) :: np
      real(wp) :: yl, yu, dy
      real(wp), allocatable :: vx(:), vy(:), ux(:), uy(:), fx(:), fy(:)
      integer, allocatable :: mat(:), cons(:)
      type(zone_list_t) :: zn
      real(wp), allocatable :: sxx0(:), sxy0(:)
      integer :: base_code(2)
      logical :: base_visc(2)
      real(wp) :: base_v(2), base_s(2), base_f(2)
      integer :: base_h
      real(wp) :: base_freq, base_tload
   end type ffield_mirror

   call test_mirrors()
   call test_round_trip()
   call test_growth_after_restart()
   call test_empty_model()
   call test_field_newer_than_file()
   call testing_finish()

contains

   !> Sizes in bits of each model type against its mirror (same compiler,
   !> same layout rules): a new field changes the size.
   subroutine test_mirrors()
      type(block_list_t) :: b
      type(block_list_mirror) :: bm
      type(corner_list_t) :: c
      type(corner_list_mirror) :: cm
      type(contact_list_t) :: k
      type(contact_list_mirror) :: km
      type(joint_state_t) :: j
      type(joint_state_mirror) :: jm
      type(domain_list_t) :: d
      type(domain_list_mirror) :: dm
      type(pending_list_t) :: p
      type(pending_list_mirror) :: pm
      type(tunnel_list_t) :: t
      type(tunnel_list_mirror) :: tm
      type(jplot_list_t) :: jp
      type(jplot_list_mirror) :: jpm
      type(gridpoint_list_t) :: gpl
      type(gridpoint_list_mirror) :: gplm
      type(zone_list_t) :: zl
      type(zone_list_mirror) :: zlm
      type(geometry_t) :: g
      type(geometry_mirror) :: gm
      type(mechanics_t) :: me
      type(mechanics_mirror) :: mem
      type(history_t) :: h
      type(history_mirror) :: hm
      type(material_table_t) :: mt
      type(material_table_mirror) :: mtm
      type(model_t) :: mo
      type(model_mirror) :: mom
      type(boundary_t) :: bd
      type(boundary_mirror) :: bdm
      type(boundary_table_t) :: bt
      type(boundary_table_mirror) :: btm
      type(zpress_t) :: zpt
      type(zpress_mirror) :: zptm
      type(be_t) :: bet
      type(be_mirror) :: betm
      type(structure_t) :: stt
      type(structure_mirror) :: sttm
      type(structure_node_list_t) :: stn
      type(structure_node_mirror) :: stnm
      type(structure_element_list_t) :: ste
      type(structure_element_mirror) :: stem
      type(structure_interface_list_t) :: sti
      type(structure_interface_mirror) :: stim
      type(fluid_t) :: flt
      type(fluid_mirror) :: fltm
      type(thermal_t) :: tht
      type(thermal_mirror) :: thtm
      type(ffield_t) :: fft
      type(ffield_mirror) :: fftm
      character(len=*), parameter :: hint = ' changed: save the new field in io_schema, ' // &
         'fill and compare it in testing_model, then extend the mirror here'
      call check(storage_size(b) == storage_size(bm), 'block_list_t'//hint)
      call check(storage_size(c) == storage_size(cm), 'corner_list_t'//hint)
      call check(storage_size(k) == storage_size(km), 'contact_list_t'//hint)
      call check(storage_size(j) == storage_size(jm), 'joint_state_t'//hint)
      call check(storage_size(d) == storage_size(dm), 'domain_list_t'//hint)
      call check(storage_size(p) == storage_size(pm), 'pending_list_t'//hint)
      call check(storage_size(t) == storage_size(tm), 'tunnel_list_t'//hint)
      call check(storage_size(jp) == storage_size(jpm), 'jplot_list_t'//hint)
      call check(storage_size(gpl) == storage_size(gplm), 'gridpoint_list_t'//hint)
      call check(storage_size(zl) == storage_size(zlm), 'zone_list_t'//hint)
      call check(storage_size(g) == storage_size(gm), 'geometry_t'//hint)
      call check(storage_size(me) == storage_size(mem), 'mechanics_t'//hint)
      call check(storage_size(h) == storage_size(hm), 'history_t'//hint)
      call check(storage_size(mt) == storage_size(mtm), 'material_table_t'//hint)
      call check(storage_size(mo) == storage_size(mom), 'model_t'//hint)
      call check(storage_size(bd) == storage_size(bdm), 'boundary_t'//hint)
      call check(storage_size(bt) == storage_size(btm), 'boundary_table_t'//hint)
      call check(storage_size(zpt) == storage_size(zptm), 'zpress_t'//hint)
      call check(storage_size(bet) == storage_size(betm), 'be_t'//hint)
      call check(storage_size(stt) == storage_size(sttm), 'structure_t'//hint)
      call check(storage_size(stn) == storage_size(stnm), 'structure_node_list_t'//hint)
      call check(storage_size(ste) == storage_size(stem), 'structure_element_list_t'//hint)
      call check(storage_size(sti) == storage_size(stim), 'structure_interface_list_t'//hint)
      call check(storage_size(flt) == storage_size(fltm), 'fluid_t'//hint)
      call check(storage_size(tht) == storage_size(thtm), 'thermal_t'//hint)
      call check(storage_size(fft) == storage_size(fftm), 'ffield_t'//hint)
   end subroutine test_mirrors

   subroutine test_round_trip()
      type(model_t) :: original, restored
      type(error_t), allocatable :: error
      character(len=*), parameter :: file = 'test_save_restart_1.sav'
      integer(ip) :: id
      call fill_model(original, 20240611_i8)
      call io_save_model(original, file, error)
      call check(.not. allocated(error), 'round trip: save succeeds')
      if (allocated(error)) then
         print '(a)', error%message
         return
      end if
      ! the target already holds a different model: everything must be replaced
      call model_reset(restored)
      call geometry_add_block(restored%geometry, [0.0_wp, 0.0_wp, 1.0_wp], &
                              [0.0_wp, 1.0_wp, 0.0_wp], 1_ip, 1_ip, id)
      call geometry_add_contact(restored%geometry, id)
      call io_load_model(restored, file, error)
      call check(.not. allocated(error), 'round trip: restart succeeds')
      if (allocated(error)) then
         print '(a)', error%message
         return
      end if
      call compare_models(original, restored, 'round trip')
      ! entries beyond n are not saved and come back zero
      call check(all(restored%geometry%blocks%area(restored%geometry%blocks%n + 1:) == 0.0_wp), &
                 'round trip: block entries beyond n are zero')
      call check(.not. any(logical(restored%geometry%contacts%live(restored%geometry%contacts%n + 1:))), &
                 'round trip: contact entries beyond n are not live')
      ! a second save of the restored model restores the same again
      call io_save_model(restored, file, error)
      call check(.not. allocated(error), 'round trip: second save succeeds')
      call model_reset(restored)
      call io_load_model(restored, file, error)
      call check(.not. allocated(error), 'round trip: second restart succeeds')
      call compare_models(original, restored, 'second round trip')
      if (posix_unlink(file)) continue
   end subroutine test_round_trip

   !> A real model (capacity 64 blocks by default) saved, restored and grown
   !> past its capacity: the lists double as before the restart.
   subroutine test_growth_after_restart()
      type(model_t) :: m, r
      type(error_t), allocatable :: error
      character(len=*), parameter :: file = 'test_save_restart_2.sav'
      integer(ip) :: i, id, capacity
      call model_reset(m)
      do i = 1, 10
         call geometry_add_block(m%geometry, real(i, wp) + [0.0_wp, 0.0_wp, 1.0_wp], &
                                 [0.0_wp, 1.0_wp, 0.0_wp], 1_ip, 1_ip, id)
      end do
      capacity = size(m%geometry%blocks%live)
      call io_save_model(m, file, error)
      call check(.not. allocated(error), 'growth: save succeeds')
      call io_load_model(r, file, error)
      call check(.not. allocated(error), 'growth: restart succeeds')
      if (allocated(error)) return
      call check_equal(size(r%geometry%blocks%live), capacity, 'growth: block capacity kept')
      do i = 11, capacity + 5
         call geometry_add_block(r%geometry, real(i, wp) + [0.0_wp, 0.0_wp, 1.0_wp], &
                                 [0.0_wp, 1.0_wp, 0.0_wp], 1_ip, 1_ip, id)
         call geometry_add_block(m%geometry, real(i, wp) + [0.0_wp, 0.0_wp, 1.0_wp], &
                                 [0.0_wp, 1.0_wp, 0.0_wp], 1_ip, 1_ip, id)
      end do
      call check_equal(int(r%geometry%blocks%n), int(capacity + 5), 'growth: blocks added')
      call compare_models(m, r, 'growth after restart')
      if (posix_unlink(file)) continue
   end subroutine test_growth_after_restart

   !> START's empty model (unallocated contact, domain and pending arrays)
   !> round-trips too: unallocated stays unallocated.
   subroutine test_empty_model()
      type(model_t) :: m, r
      type(error_t), allocatable :: error
      character(len=*), parameter :: file = 'test_save_restart_3.sav'
      integer(ip) :: id
      call model_reset(m)
      call io_save_model(m, file, error)
      call check(.not. allocated(error), 'empty: save succeeds')
      call fill_model(r, 7_i8)
      call io_load_model(r, file, error)
      call check(.not. allocated(error), 'empty: restart succeeds')
      if (allocated(error)) return
      call compare_models(m, r, 'empty model')
      call check(.not. allocated(r%geometry%contacts%live), 'empty: contacts unallocated')
      call geometry_add_contact(r%geometry, id)
      call check_equal(int(id), 1, 'empty: first contact after restart')
      if (posix_unlink(file)) continue
   end subroutine test_empty_model

   !> Schema evolution: reading a file of version 1 with a walker that has a
   !> field of version 2 (`since=2`) keeps the scalar's default and gives the
   !> array zeros with the capacity of the list read before it; a field the
   !> file should have (no `since`) but lacks is an error naming it.
   subroutine test_field_newer_than_file()
      type(stream_t) :: s
      character(len=*), parameter :: file = 'test_save_restart_4.sav'
      integer(ip) :: n
      real(wp), allocatable :: a(:), b(:), c(:)
      real(wp) :: scalar
      n = 3
      allocate (a(8))
      a = [1.0_wp, 2.0_wp, 3.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]
      call s%create(file)
      call s%begin_group('list')
      call s%attr('n', n)
      call s%field('a', a, n)
      call s%end_group()
      call s%close()
      call check(.not. s%failed(), 'evolution: version 1 file written')
      deallocate (a)
      n = -1
      scalar = 42.0_wp
      call s%open(file)
      s%version = 1
      call s%begin_group('list')
      call s%attr('n', n)
      call s%field('a', a, n)
      call s%field('b', b, n, since=2)
      call s%attr('scalar', scalar, since=2)
      call check(.not. s%failed(), 'evolution: fields newer than the file are skipped')
      call check_equal(int(n), 3, 'evolution: n read')
      call check(allocated(b), 'evolution: newer array allocated')
      if (allocated(b)) then
         call check_equal(size(b), 8, 'evolution: newer array has the list capacity')
         call check(all(b == 0.0_wp), 'evolution: newer array is zero')
      end if
      call check(scalar == 42.0_wp, 'evolution: newer scalar keeps its default')
      call s%field('c', c, n)
      call check(s%failed(), 'evolution: a missing field of the file''s version is an error')
      if (s%failed()) call check(index(s%message, '/list/c') > 0, &
                                 'evolution: the error names the field')
      call s%close()
      if (posix_unlink(file)) continue
   end subroutine test_field_newer_than_file

end program test_save_restart
