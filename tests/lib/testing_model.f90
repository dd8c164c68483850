!> Test helpers over the whole model: fill every field of a model_t with
!> distinct values, and compare two models field by field exactly (reals bit
!> for bit). Used by the save/restart tests.
!>
!> When a field is added to model_t or one of its parts, add it to
!> `fill_model` and `compare_models` here (and to io_schema's walker);
!> tests/unit/test_save_restart.f90 checks the type sizes and fails until
!> its mirror types are extended too.
module testing_model
   use core_kinds, only: wp, ip, i8, i1, l1
   use model_state, only: model_t
   use model_properties, only: nproperties
   use model_geometry, only: geometry_t, block_list_t, corner_list_t, contact_list_t, &
                             joint_state_t, domain_list_t, pending_list_t, tunnel_list_t, &
                             jplot_list_t
   use model_zones, only: gridpoint_list_t, zone_list_t
   use model_mechanics, only: mechanics_t
   use model_history, only: history_t
   use model_boundary, only: boundary_t, boundary_table_t, zpress_t
   use model_be, only: be_t
   use model_reinforcement, only: reinforcement_t
   use model_structures, only: structure_t, structure_node_list_t, structure_element_list_t, &
                               structure_interface_list_t
   use model_fluid, only: fluid_t
   use model_thermal, only: thermal_t
   use model_ffield, only: ffield_t
   use testing, only: check
   implicit none
   private
   public :: fill_model, compare_models

   !> Source of distinct values: a counter (distinctness) plus xorshift bits.
   type :: filler_t
      integer(i8) :: counter = 0_i8
      integer(i8) :: state = 88172645463325252_i8
   end type filler_t

   interface same
      module procedure same_real, same_int, same_i8, same_log, same_reals, same_text
      module procedure same_real_list, same_int_list, same_log_list, same_code_list, same_log1_list
      module procedure same_real_table, same_log_table
   end interface same

contains

   ! ---- filling -----------------------------------------------------------------

   integer(i8) function next_bits(f) result(bits)
      type(filler_t), intent(inout) :: f
      f%state = ieor(f%state, ishft(f%state, 13))
      f%state = ieor(f%state, ishft(f%state, -7))
      f%state = ieor(f%state, ishft(f%state, 17))
      f%counter = f%counter + 1_i8
      bits = f%state
   end function next_bits

   !> Distinct reals of both signs with random low-order bits.
   real(wp) function next_real(f) result(r)
      type(filler_t), intent(inout) :: f
      integer(i8) :: bits
      bits = next_bits(f)
      r = real(f%counter, wp) + real(ishft(bits, -11), wp)*2.0_wp**(-53)
      if (btest(bits, 3)) r = -r
      r = r*1.0e-3_wp
   end function next_real

   integer(ip) function next_int(f) result(i)
      type(filler_t), intent(inout) :: f
      integer(i8) :: bits
      bits = next_bits(f)
      i = int(f%counter, ip)
      if (btest(bits, 5)) i = -i
   end function next_int

   logical function next_log(f) result(l)
      type(filler_t), intent(inout) :: f
      l = btest(next_bits(f), 7)
   end function next_log

   subroutine fill_reals(f, a, cap)
      type(filler_t), intent(inout) :: f
      real(wp), allocatable, intent(inout) :: a(:)
      integer(ip), intent(in) :: cap
      integer(ip) :: i
      if (allocated(a)) deallocate (a)
      allocate (a(cap))
      do i = 1, cap
         a(i) = next_real(f)
      end do
   end subroutine fill_reals

   subroutine fill_ints(f, a, cap)
      type(filler_t), intent(inout) :: f
      integer, allocatable, intent(inout) :: a(:)
      integer(ip), intent(in) :: cap
      integer(ip) :: i
      if (allocated(a)) deallocate (a)
      allocate (a(cap))
      do i = 1, cap
         a(i) = next_int(f)
      end do
   end subroutine fill_ints

   !> A 2-D array of n1 x n2 reals, filled in storage order (first index fastest).
   subroutine fill_reals_2d(f, a, n1, n2)
      type(filler_t), intent(inout) :: f
      real(wp), allocatable, intent(inout) :: a(:, :)
      integer(ip), intent(in) :: n1, n2
      integer(ip) :: i, j
      if (allocated(a)) deallocate (a)
      allocate (a(n1, n2))
      do j = 1, n2
         do i = 1, n1
            a(i, j) = next_real(f)
         end do
      end do
   end subroutine fill_reals_2d

   !> One-byte codes (a contact's kind, jcons): the next integer folded into
   !> -127 .. 127.
   subroutine fill_codes(f, a, cap)
      type(filler_t), intent(inout) :: f
      integer(i1), allocatable, intent(inout) :: a(:)
      integer(ip), intent(in) :: cap
      integer(ip) :: i
      if (allocated(a)) deallocate (a)
      allocate (a(cap))
      do i = 1, cap
         a(i) = int(modulo(next_int(f), 255_ip) - 127_ip, i1)
      end do
   end subroutine fill_codes

   subroutine fill_logs(f, a, cap)
      type(filler_t), intent(inout) :: f
      logical, allocatable, intent(inout) :: a(:)
      integer(ip), intent(in) :: cap
      integer(ip) :: i
      if (allocated(a)) deallocate (a)
      allocate (a(cap))
      do i = 1, cap
         a(i) = next_log(f)
      end do
   end subroutine fill_logs

   !> fill_logs for the one-byte logicals of the entity lists (live marks,
   !> block flags): the same values, converted
   subroutine fill_logs1(f, a, cap)
      type(filler_t), intent(inout) :: f
      logical(l1), allocatable, intent(inout) :: a(:)
      integer(ip), intent(in) :: cap
      logical, allocatable :: t(:)
      call fill_logs(f, t, cap)
      a = logical(t, l1)
   end subroutine fill_logs1

   !> Every field of `m` gets a distinct value; list `k` holds n = 3 + k
   !> entries in arrays of capacity n + 5 (so capacity is checked too). Some
   !> real entries are special (signed zero, subnormal, huge) to check bits.
   subroutine fill_model(m, seed)
      type(model_t), intent(out) :: m
      integer(i8), intent(in) :: seed
      type(filler_t) :: f
      integer(ip) :: n, cap, i, j
      f%state = ieor(f%state, seed*2654435761_i8)
      if (f%state == 0_i8) f%state = 1_i8
      m%heading = 'random model, trailing blank '
      m%gravity = [next_real(f), next_real(f)]
      m%cycled = next_log(f)

      ! materials: 3 materials in a table with room for 7
      m%materials%nmat = 3
      allocate (m%materials%value(nproperties, 7), m%materials%given(nproperties, 7))
      do j = 1, 7
         do i = 1, nproperties
            m%materials%value(i, j) = next_real(f)
            m%materials%given(i, j) = next_log(f)
         end do
      end do

      associate (g => m%geometry)
         g%round = next_real(f)
         g%edge_min = next_real(f)
         g%edge_set = next_log(f)
         g%tol = next_real(f)
         g%extent = next_real(f)
         g%original_area = next_real(f)
         g%deleted_area = next_real(f)
         g%block_created = next_log(f)
         g%has_jregion = next_log(f)
         do i = 1, 4
            g%jregion_x(i) = next_real(f)
            g%jregion_y(i) = next_real(f)
         end do
         g%rng_state = next_bits(f)
         g%jmat_default = next_int(f)
         g%jcons_default = next_int(f)
         g%contacts_valid = next_log(f)
         g%domains_valid = next_log(f)
         g%outer_domain = next_int(f)
         g%ia%mfree = next_int(f)
         g%ia%outer = next_int(f)
         g%ia%njunk = 3
         call fill_ints(f, g%ia%junk_addr, 5_ip)
         call fill_ints(f, g%ia%junk_len, 5_ip)
         do i = 1, size(g%cut_stats)
            g%cut_stats(i) = next_int(f)
         end do
         g%nrefused_keys = 2
         call fill_reals_2d(f, g%refused_keys, 6_ip, 3_ip)
         g%mechanical = next_log(f)

         n = 4; cap = n + 5
         g%blocks%n = n
         call fill_logs1(f, g%blocks%live, cap)
         call fill_ints(f, g%blocks%first_corner, cap)
         call fill_ints(f, g%blocks%ncorner, cap)
         call fill_ints(f, g%blocks%material, cap)
         call fill_ints(f, g%blocks%cons, cap)
         call fill_reals(f, g%blocks%area, cap)
         call fill_reals(f, g%blocks%xc, cap)
         call fill_reals(f, g%blocks%yc, cap)
         call fill_reals(f, g%blocks%xmin, cap)
         call fill_reals(f, g%blocks%xmax, cap)
         call fill_reals(f, g%blocks%ymin, cap)
         call fill_reals(f, g%blocks%ymax, cap)
         call fill_reals(f, g%blocks%mass, cap)
         call fill_reals(f, g%blocks%inertia, cap)
         call fill_reals(f, g%blocks%vx, cap)
         call fill_reals(f, g%blocks%vy, cap)
         call fill_reals(f, g%blocks%vr, cap)
         call fill_reals(f, g%blocks%ux, cap)
         call fill_reals(f, g%blocks%uy, cap)
         call fill_reals(f, g%blocks%rot, cap)
         call fill_reals(f, g%blocks%fx, cap)
         call fill_reals(f, g%blocks%fy, cap)
         call fill_reals(f, g%blocks%fm, cap)
         call fill_reals(f, g%blocks%lx, cap)
         call fill_reals(f, g%blocks%ly, cap)
         call fill_logs1(f, g%blocks%fixed, cap)
         call fill_logs1(f, g%blocks%fdef, cap)
         call fill_ints(f, g%blocks%zfirst, cap)
         call fill_ints(f, g%blocks%nzone, cap)
         call fill_ints(f, g%blocks%gfirst, cap)
         call fill_ints(f, g%blocks%ngp, cap)
         call fill_ints(f, g%blocks%addr, cap)
         call fill_logs1(f, g%blocks%sdef, cap)
         call fill_reals(f, g%blocks%exx, cap)
         call fill_reals(f, g%blocks%eyy, cap)
         call fill_reals(f, g%blocks%exy, cap)
         call fill_reals(f, g%blocks%dxx, cap)
         call fill_reals(f, g%blocks%dyy, cap)
         call fill_reals(f, g%blocks%dxy, cap)
         call fill_reals(f, g%blocks%sxx, cap)
         call fill_reals(f, g%blocks%syy, cap)
         call fill_reals(f, g%blocks%sxy, cap)
         call fill_reals(f, g%blocks%qxx, cap)
         call fill_reals(f, g%blocks%qyy, cap)
         call fill_reals(f, g%blocks%qxy, cap)
         call fill_ints(f, g%blocks%bstate, cap)
         g%blocks%vx(1) = -0.0_wp
         g%blocks%vx(2) = tiny(1.0_wp)*0.25_wp
         g%blocks%vx(3) = -huge(1.0_wp)

         n = 5; cap = n + 5
         g%corners%n = n
         call fill_logs1(f, g%corners%live, cap)
         call fill_reals(f, g%corners%x, cap)
         call fill_reals(f, g%corners%y, cap)
         call fill_ints(f, g%corners%block, cap)
         call fill_ints(f, g%corners%next, cap)
         call fill_ints(f, g%corners%prev, cap)
         call fill_reals(f, g%corners%rx, cap)
         call fill_reals(f, g%corners%ry, cap)
         call fill_reals(f, g%corners%radius, cap)
         call fill_reals(f, g%corners%ux, cap)
         call fill_reals(f, g%corners%uy, cap)
         call fill_ints(f, g%corners%gp, cap)
         call fill_ints(f, g%corners%addr, cap)

         n = 6; cap = n + 5
         g%contacts%n = n
         call fill_logs1(f, g%contacts%live, cap)
         call fill_ints(f, g%contacts%block1, cap)
         call fill_ints(f, g%contacts%block2, cap)
         call fill_codes(f, g%contacts%kind, cap)
         call fill_ints(f, g%contacts%end1, cap)
         call fill_ints(f, g%contacts%end2, cap)
         call fill_ints(f, g%contacts%jmat, cap)
         call fill_codes(f, g%contacts%jcons, cap)
         call fill_ints(f, g%contacts%dom1, cap)
         call fill_ints(f, g%contacts%dom2, cap)
         call fill_reals(f, g%contacts%x, cap)
         call fill_reals(f, g%contacts%y, cap)
         call fill_reals(f, g%contacts%nx, cap)
         call fill_reals(f, g%contacts%ny, cap)
         call fill_reals(f, g%contacts%length, cap)
         call fill_reals(f, g%contacts%gap, cap)
         call fill_reals(f, g%contacts%state%fn, cap)
         call fill_reals(f, g%contacts%state%fs, cap)
         call fill_reals(f, g%contacts%state%un, cap)
         call fill_reals(f, g%contacts%state%us, cap)
         call fill_codes(f, g%contacts%state%flags, cap)
         call fill_reals(f, g%contacts%state%ud, cap)
         call fill_reals(f, g%contacts%state%phi_eff, cap)
         call fill_reals(f, g%contacts%state%reversal, cap)
         call fill_reals(f, g%contacts%state%dus_old, cap)
         call fill_ints(f, g%contacts%addr, cap)

         n = 7; cap = n + 5
         g%domains%n = n
         call fill_logs1(f, g%domains%live, cap)
         call fill_logs1(f, g%domains%outer, cap)
         call fill_reals(f, g%domains%area, cap)
         call fill_ints(f, g%domains%first, cap)
         call fill_ints(f, g%domains%count, cap)
         call fill_ints(f, g%domains%addr, cap)
         g%domains%nring = 11
         call fill_ints(f, g%domains%ring, 13_ip)

         n = 8; cap = n + 5
         g%pending%n = n
         call fill_reals(f, g%pending%x1, cap)
         call fill_reals(f, g%pending%y1, cap)
         call fill_reals(f, g%pending%x2, cap)
         call fill_reals(f, g%pending%y2, cap)

         n = 9; cap = n + 5
         g%tunnels%n = n
         call fill_reals(f, g%tunnels%xc, cap)
         call fill_reals(f, g%tunnels%yc, cap)
         call fill_reals(f, g%tunnels%r, cap)
         call fill_ints(f, g%tunnels%nside, cap)

         n = 10; cap = n + 5
         g%jplot%on = next_log(f)
         g%jplot%n = n
         call fill_reals(f, g%jplot%x1, cap)
         call fill_reals(f, g%jplot%y1, cap)
         call fill_reals(f, g%jplot%x2, cap)
         call fill_reals(f, g%jplot%y2, cap)
         call fill_ints(f, g%jplot%block, cap)

         n = 7; cap = n + 5
         g%gridpoints%n = n
         call fill_logs1(f, g%gridpoints%live, cap)
         call fill_ints(f, g%gridpoints%block, cap)
         call fill_ints(f, g%gridpoints%corner, cap)
         call fill_reals(f, g%gridpoints%x, cap)
         call fill_reals(f, g%gridpoints%y, cap)
         call fill_reals(f, g%gridpoints%vx, cap)
         call fill_reals(f, g%gridpoints%vy, cap)
         call fill_reals(f, g%gridpoints%ux, cap)
         call fill_reals(f, g%gridpoints%uy, cap)
         call fill_reals(f, g%gridpoints%fx, cap)
         call fill_reals(f, g%gridpoints%fy, cap)
         call fill_reals(f, g%gridpoints%mass, cap)
         call fill_ints(f, g%gridpoints%vfix, cap)
         call fill_ints(f, g%gridpoints%addr, cap)

         n = 8; cap = n + 5
         g%zones%n = n
         call fill_logs1(f, g%zones%live, cap)
         call fill_ints(f, g%zones%block, cap)
         call fill_ints(f, g%zones%g1, cap)
         call fill_ints(f, g%zones%g2, cap)
         call fill_ints(f, g%zones%g3, cap)
         call fill_reals(f, g%zones%sxx, cap)
         call fill_reals(f, g%zones%sxy, cap)
         call fill_reals(f, g%zones%syy, cap)
         call fill_reals(f, g%zones%szz, cap)
         call fill_ints(f, g%zones%state, cap)
         call fill_ints(f, g%zones%addr, cap)
      end associate

      associate (c => m%mech)
         c%time = next_real(f)
         c%step = next_bits(f)
         c%dt = next_real(f)
         c%frac_block = next_real(f)
         c%frac_zone = next_real(f)
         c%frac_fluid = next_real(f)
         c%damping = next_int(f)
         c%auto_fac = next_real(f)
         c%auto_mult1 = next_real(f)
         c%auto_mult2 = next_real(f)
         c%auto_alpha = next_real(f)
         c%local_alpha = next_real(f)
         c%kinetic_old = next_real(f)
         c%rayleigh_fcrit = next_real(f)
         c%rayleigh_freq = next_real(f)
         c%rayleigh_mass = next_log(f)
         c%rayleigh_stiff = next_log(f)
         c%internal_fcrit = next_real(f)
         c%internal_freq = next_real(f)
         c%internal_mass = next_log(f)
         c%internal_stiff = next_log(f)
         c%mscale = next_log(f)
         c%mscale_zone = next_real(f)
         c%mscale_block = next_real(f)
         c%mscale_part = next_log(f)
         c%mscale_tdel = next_real(f)
         c%nupcon = next_int(f)
         c%dscan = next_int(f)
         c%cscan = next_int(f)
         c%ovtol = next_real(f)
         c%clemin = next_real(f)
         c%clemin_auto = next_real(f)
         c%motion_since_scan = next_real(f)
         c%unbalanced = next_real(f)
         c%masses_valid = next_log(f)
         c%fxhis = next_real(f)
         c%fyhis = next_real(f)
         c%search_current = next_log(f)
         c%search_sizes(1) = next_int(f)
         c%search_sizes(2) = next_int(f)
         c%search_sizes(3) = next_int(f)
         c%search_margin = next_real(f)
         c%probe_time = next_real(f)
         c%probe_w = next_real(f)
         c%probe_wref = next_real(f)
      end associate

      associate (h => m%hist)
         h%n = 3
         call fill_ints(f, h%kind, 3_ip)
         call fill_ints(f, h%entity, 3_ip)
         call fill_reals(f, h%x, 3_ip)
         call fill_reals(f, h%y, 3_ip)
         call fill_reals(f, h%px, 3_ip)
         call fill_reals(f, h%py, 3_ip)
         h%ncyc = next_int(f)
         h%typed = next_int(f)
         h%nsample = 10
         call fill_reals(f, h%time, 16_ip)
         call fill_ints(f, h%step, 16_ip)
         call fill_reals_2d(f, h%values, 3_ip, 16_ip)
         call fill_ints(f, h%first_sample, 3_ip)
      end associate

      associate (b => m%bound)
         n = 6; cap = n + 4
         b%n = n
         b%corners_seen = next_int(f)
         b%t_start = next_real(f)
         call fill_ints(f, b%corner, cap)
         call fill_ints(f, b%ix, cap)
         call fill_ints(f, b%iy, cap)
         call fill_reals(f, b%fx, cap)
         call fill_reals(f, b%fy, cap)
         call fill_reals(f, b%dfx, cap)
         call fill_reals(f, b%dfy, cap)
         call fill_ints(f, b%hx, cap)
         call fill_ints(f, b%hy, cap)
         call fill_reals(f, b%freqx, cap)
         call fill_reals(f, b%tloadx, cap)
         call fill_reals(f, b%freqy, cap)
         call fill_reals(f, b%tloady, cap)
         call fill_reals(f, b%xmul, cap)
         call fill_reals(f, b%ymul, cap)
         call fill_reals(f, b%vx, cap)
         call fill_reals(f, b%vy, cap)
         call fill_ints(f, b%vis, cap)
         call fill_ints(f, b%vmat, cap)
         call fill_ints(f, b%ff, cap)
         b%fup = .false.      ! not the default, so a lost flag shows
         call fill_reals(f, b%sxx_prev, cap)
         call fill_reals(f, b%sxy_prev, cap)
         call fill_reals(f, b%syy_prev, cap)
         call fill_reals(f, b%sxx_next, cap)
         call fill_reals(f, b%sxy_next, cap)
         call fill_reals(f, b%syy_next, cap)
         call fill_reals(f, b%dsxx_prev, cap)
         call fill_reals(f, b%dsxy_prev, cap)
         call fill_reals(f, b%dsyy_prev, cap)
         call fill_reals(f, b%dsxx_next, cap)
         call fill_reals(f, b%dsxy_next, cap)
         call fill_reals(f, b%dsyy_next, cap)
         call fill_ints(f, b%end_prev, cap)
         call fill_ints(f, b%end_next, cap)
         b%table(1)%heading = 'accelerogram 1'
         b%table(1)%np = 5
         b%table(1)%dt = next_real(f)
         call fill_reals(f, b%table(1)%values, 7_ip)
         ! table 2 left unread: its values stay unallocated
      end associate

      associate (z => m%bound%zp)
         n = 3; cap = n + 2
         z%n = n
         z%h_next = next_int(f)
         z%freq_next = next_real(f)
         z%tload_next = next_real(f)
         call fill_reals(f, z%x, cap)
         call fill_reals(f, z%y, cap)
         call fill_reals(f, z%rad, cap)
         call fill_reals(f, z%pz, cap)
         call fill_ints(f, z%h, cap)
         call fill_reals(f, z%freq, cap)
         call fill_reals(f, z%tload, cap)
         call fill_ints(f, z%nzone, cap)
         z%nz = 7
         call fill_ints(f, z%zone, 11_ip)
         call fill_ints(f, z%src, 11_ip)
      end associate

      associate (e => m%be)
         e%mat = int(next_int(f))
         e%half = .true.
         e%fix = .true.
         e%xh = next_real(f); e%yh = next_real(f)
         e%xv = next_real(f); e%yv = next_real(f)
         e%nc = 4; e%ne = 3
         call fill_ints(f, e%corner, e%nc)
         call fill_ints(f, e%ea, e%ne)
         call fill_ints(f, e%eb, e%ne)
         e%linked = .true.
         e%g = next_real(f); e%nu = next_real(f)
         call fill_reals(f, e%x0, e%nc)
         call fill_reals(f, e%y0, e%nc)
         ! kmat, u, f are work: left unallocated
      end associate

      allocate (m%structures)
      associate (nd => m%structures%nodes, el => m%structures%elements, &
                 it => m%structures%interfaces)
         nd%n = 5
         cap = 9
         call fill_reals(f, nd%x, cap); call fill_reals(f, nd%y, cap)
         call fill_reals(f, nd%vx, cap); call fill_reals(f, nd%vy, cap)
         call fill_reals(f, nd%vr, cap)
         call fill_reals(f, nd%ux, cap); call fill_reals(f, nd%uy, cap)
         call fill_reals(f, nd%rot, cap)
         call fill_reals(f, nd%fx, cap); call fill_reals(f, nd%fy, cap)
         call fill_reals(f, nd%fm, cap)
         call fill_reals(f, nd%mass, cap); call fill_reals(f, nd%inertia, cap)
         call fill_reals(f, nd%lx, cap); call fill_reals(f, nd%ly, cap)
         call fill_ints(f, nd%fix, cap); call fill_ints(f, nd%material, cap)
         el%n = 4
         cap = 6
         call fill_ints(f, el%n1, cap); call fill_ints(f, el%n2, cap)
         call fill_ints(f, el%material, cap)
         call fill_reals(f, el%thick, cap)
         call fill_reals(f, el%length0, cap); call fill_reals(f, el%angle0, cap)
         call fill_reals(f, el%young, cap); call fill_reals(f, el%area, cap)
         call fill_reals(f, el%inertia, cap)
         call fill_reals(f, el%axial, cap); call fill_reals(f, el%shear, cap)
         call fill_reals(f, el%m1, cap); call fill_reals(f, el%m2, cap)
         it%n = 5
         cap = 7
         call fill_ints(f, it%node, cap); call fill_ints(f, it%block, cap)
         call fill_ints(f, it%edge, cap); call fill_ints(f, it%material, cap)
         call fill_reals(f, it%x, cap); call fill_reals(f, it%y, cap)
         call fill_reals(f, it%nx, cap); call fill_reals(f, it%ny, cap)
         call fill_reals(f, it%un, cap); call fill_reals(f, it%us, cap)
         call fill_reals(f, it%fn, cap); call fill_reals(f, it%fs, cap)
         call fill_ints(f, it%flags, cap)
      end associate
      allocate (m%reinforcement)
      associate (r => m%reinforcement%reinf, cn => m%reinforcement%nodes, &
                 ce => m%reinforcement%elements)
         m%reinforcement%ncable = int(next_int(f))
         r%n = 3
         cap = 4
         call fill_ints(f, r%material, cap); call fill_ints(f, r%block1, cap)
         call fill_ints(f, r%block2, cap); call fill_ints(f, r%g1a, cap)
         call fill_ints(f, r%g1b, cap); call fill_ints(f, r%g2a, cap)
         call fill_ints(f, r%g2b, cap)
         call fill_reals(f, r%w1, cap); call fill_reals(f, r%w2, cap)
         call fill_reals(f, r%x1, cap); call fill_reals(f, r%y1, cap)
         call fill_reals(f, r%x2, cap); call fill_reals(f, r%y2, cap)
         call fill_reals(f, r%ax, cap); call fill_reals(f, r%ay, cap)
         call fill_reals(f, r%tx, cap); call fill_reals(f, r%ty, cap)
         call fill_reals(f, r%dx, cap); call fill_reals(f, r%dy, cap)
         call fill_reals(f, r%uaxial, cap); call fill_reals(f, r%fa, cap)
         call fill_reals(f, r%fs, cap); call fill_reals(f, r%fjs, cap)
         call fill_reals(f, r%fjn, cap)
         cn%n = 4
         cap = 5
         call fill_ints(f, cn%cable, cap); call fill_ints(f, cn%block, cap)
         call fill_ints(f, cn%zone, cap); call fill_ints(f, cn%matg, cap)
         call fill_reals(f, cn%w1, cap); call fill_reals(f, cn%w2, cap)
         call fill_reals(f, cn%w3, cap)
         call fill_reals(f, cn%x, cap); call fill_reals(f, cn%y, cap)
         call fill_reals(f, cn%hx, cap); call fill_reals(f, cn%hy, cap)
         call fill_reals(f, cn%vs, cap); call fill_reals(f, cn%vx, cap)
         call fill_reals(f, cn%vy, cap); call fill_reals(f, cn%fx, cap)
         call fill_reals(f, cn%fy, cap); call fill_reals(f, cn%fg, cap)
         call fill_reals(f, cn%slip, cap); call fill_reals(f, cn%glen, cap)
         call fill_reals(f, cn%mass, cap)
         ce%n = 3
         cap = 4
         call fill_ints(f, ce%cable, cap); call fill_ints(f, ce%n1, cap)
         call fill_ints(f, ce%n2, cap); call fill_ints(f, ce%mats, cap)
         call fill_reals(f, ce%area, cap); call fill_reals(f, ce%length0, cap)
         call fill_reals(f, ce%length, cap); call fill_reals(f, ce%axial, cap)
         call fill_reals(f, ce%pre, cap)
      end associate
      allocate (m%fluid)
      associate (fl => m%fluid)
         fl%rhow = next_real(f); fl%bulkw = next_real(f); fl%cohw = next_real(f)
         fl%capratio = next_real(f)
         fl%sflow = .true.
         fl%eff = .false.
         fl%ywtab = next_real(f); fl%ptol = next_real(f)
         fl%nd = 5
         call fill_reals(f, fl%p, 8_ip)
         call fill_logs(f, fl%fixed, 8_ip)
         call fill_reals(f, fl%vol, 8_ip)
         call fill_reals(f, fl%xd, 8_ip)
         call fill_reals(f, fl%yd, 8_ip)
         fl%nc = 6
         call fill_reals(f, fl%aperture, 9_ip)
         call fill_reals(f, fl%q, 9_ip)
         call fill_ints(f, fl%bnd_code, 9_ip)
         call fill_reals(f, fl%bnd_p, 9_ip)
         call fill_reals(f, fl%bnd_g, 9_ip)
         call fill_ints(f, fl%cdom1, 9_ip)
         call fill_ints(f, fl%cdom2, 9_ip)
      end associate
      associate (ff => m%ffield)
         ff%on = .true.
         ff%np = 6
         ff%yl = next_real(f); ff%yu = next_real(f); ff%dy = next_real(f)
         ff%base_code = [1, 4]
         ff%base_visc = [.true., .false.]
         ff%base_v = [next_real(f), next_real(f)]
         ff%base_s = [next_real(f), next_real(f)]
         ff%base_f = [next_real(f), next_real(f)]
         ff%base_h = 2
         ff%base_freq = next_real(f); ff%base_tload = next_real(f)
         call fill_reals(f, ff%vx, 8_ip)
         call fill_reals(f, ff%vy, 8_ip)
         call fill_reals(f, ff%ux, 8_ip)
         call fill_reals(f, ff%uy, 8_ip)
         call fill_reals(f, ff%fx, 8_ip)
         call fill_reals(f, ff%fy, 8_ip)
         call fill_ints(f, ff%mat, 7_ip)
         call fill_ints(f, ff%cons, 7_ip)
         call fill_reals(f, ff%sxx0, 7_ip)
         call fill_reals(f, ff%sxy0, 7_ip)
         ff%zn%n = 5
         call fill_logs1(f, ff%zn%live, 7_ip)
         call fill_ints(f, ff%zn%block, 7_ip)
         call fill_ints(f, ff%zn%g1, 7_ip)
         call fill_ints(f, ff%zn%g2, 7_ip)
         call fill_ints(f, ff%zn%g3, 7_ip)
         call fill_reals(f, ff%zn%sxx, 7_ip)
         call fill_reals(f, ff%zn%sxy, 7_ip)
         call fill_reals(f, ff%zn%syy, 7_ip)
         call fill_reals(f, ff%zn%szz, 7_ip)
         call fill_ints(f, ff%zn%state, 7_ip)
         call fill_ints(f, ff%zn%addr, 7_ip)
      end associate
      allocate (m%thermal)
      associate (th => m%thermal)
         th%time = next_real(f); th%nsteps = 17; th%dt_user = next_real(f)
         th%age = next_real(f); th%age_test = .true.; th%temp_limit = next_real(f)
         th%step_limit = 123; th%tol = next_real(f); th%nther = 3; th%nmech = 44
         th%dt_last = next_real(f)
         th%ng = 5
         call fill_reals(f, th%temp, 7_ip)
         call fill_logs(f, th%fixed, 7_ip)
         call fill_reals(f, th%dtacc, 7_ip)
         th%nc = 6
         call fill_reals(f, th%ctemp, 9_ip)
         call fill_logs(f, th%cfixed, 9_ip)
         call fill_reals(f, th%cdtacc, 9_ip)
         th%nb = 2
         call fill_reals(f, th%btemp, 3_ip)
         call fill_logs(f, th%bfixed, 3_ip)
         call fill_reals(f, th%bdtacc, 3_ip)
         th%nrec = 4
         th%nset = 2
         call fill_ints(f, th%rec_kind, 6_ip)
         call fill_ints(f, th%rec_id, 6_ip)
         call fill_reals(f, th%rec_p1, 6_ip)
         call fill_reals(f, th%rec_p2, 6_ip)
         call fill_reals(f, th%rec_t0, 6_ip)
         call fill_ints(f, th%rec_set, 6_ip)
         th%nthis = 3; th%ntcyc = 7; th%this_type = 2
         call fill_ints(f, th%this_gp, 20_ip)
         call fill_reals(f, th%this_x, 20_ip)
         call fill_reals(f, th%this_y, 20_ip)
         call fill_ints(f, th%this_kind, 20_ip)
         th%nsamp = 2
         call fill_reals(f, th%samp_time, 4_ip)
         call fill_reals(f, th%samp_val, 80_ip)
      end associate
      m%tables%len = [3, 0, 2, 0, 0, 0, 0, 0, 0, 1]
      m%tables%ntot = 6
      call fill_reals(f, m%tables%x, 6_ip)
      call fill_reals(f, m%tables%y, 6_ip)
   end subroutine fill_model

   ! ---- comparing ---------------------------------------------------------------

   !> Check that `b` equals `a` in every field (the first n entries of each
   !> list, the allocation status and the capacity of every array).
   subroutine compare_models(a, b, label)
      type(model_t), intent(in) :: a, b
      character(len=*), intent(in) :: label
      character(len=:), allocatable :: p
      integer :: k
      p = label//': '
      call same(a%heading, b%heading, p//'heading')
      call same(a%gravity, b%gravity, p//'gravity')
      call same(a%cycled, b%cycled, p//'cycled')
      call same(a%materials%nmat, b%materials%nmat, p//'materials%nmat')
      call same(a%materials%value, b%materials%value, a%materials%nmat, p//'materials%value')
      call same(a%materials%given, b%materials%given, a%materials%nmat, p//'materials%given')
      call compare_geometry(a%geometry, b%geometry, p//'geometry%')
      call compare_mechanics(a%mech, b%mech, p//'mech%')
      call compare_history(a%hist, b%hist, p//'hist%')
      call compare_boundary(a%bound, b%bound, p//'bound%')
      call compare_be(a%be, b%be, p//'be%')
      call same(allocated(a%structures), allocated(b%structures), p//'allocated(structures)')
      if (allocated(a%structures) .and. allocated(b%structures)) &
         call compare_structures(a%structures, b%structures, p//'structures%')
      call same(allocated(a%reinforcement), allocated(b%reinforcement), &
                p//'allocated(reinforcement)')
      if (allocated(a%reinforcement) .and. allocated(b%reinforcement)) &
         call compare_reinforcement(a%reinforcement, b%reinforcement, p//'reinforcement%')
      call same(allocated(a%fluid), allocated(b%fluid), p//'allocated(fluid)')
      if (allocated(a%fluid) .and. allocated(b%fluid)) call compare_fluid(a%fluid, b%fluid, &
                                                                           p//'fluid%')
      call same(allocated(a%thermal), allocated(b%thermal), p//'allocated(thermal)')
      if (allocated(a%thermal) .and. allocated(b%thermal)) &
         call compare_thermal(a%thermal, b%thermal, p//'thermal%')
      call compare_ffield(a%ffield, b%ffield, p//'ffield%')
      call same(a%tables%ntot, b%tables%ntot, p//'tables%ntot')
      do k = 1, size(a%tables%len)
         call same(a%tables%len(k), b%tables%len(k), p//'tables%len')
      end do
      call same(a%tables%x, b%tables%x, a%tables%ntot, p//'tables%x')
      call same(a%tables%y, b%tables%y, a%tables%ntot, p//'tables%y')
   end subroutine compare_models

   subroutine compare_ffield(a, b, p)
      type(ffield_t), intent(in) :: a, b
      character(len=*), intent(in) :: p
      integer(ip) :: nz
      call same(a%on, b%on, p//'on')
      call same(a%np, b%np, p//'np')
      call same(a%yl, b%yl, p//'yl')
      call same(a%yu, b%yu, p//'yu')
      call same(a%dy, b%dy, p//'dy')
      call same(a%base_code(1), b%base_code(1), p//'base_code(1)')
      call same(a%base_code(2), b%base_code(2), p//'base_code(2)')
      call same(a%base_visc(1), b%base_visc(1), p//'base_visc(1)')
      call same(a%base_visc(2), b%base_visc(2), p//'base_visc(2)')
      call same(a%base_v, b%base_v, p//'base_v')
      call same(a%base_s, b%base_s, p//'base_s')
      call same(a%base_f, b%base_f, p//'base_f')
      call same(a%base_h, b%base_h, p//'base_h')
      call same(a%base_freq, b%base_freq, p//'base_freq')
      call same(a%base_tload, b%base_tload, p//'base_tload')
      if (a%np /= b%np) return
      call same(a%vx, b%vx, a%np, p//'vx')
      call same(a%vy, b%vy, a%np, p//'vy')
      call same(a%ux, b%ux, a%np, p//'ux')
      call same(a%uy, b%uy, a%np, p//'uy')
      call same(a%fx, b%fx, a%np, p//'fx')
      call same(a%fy, b%fy, a%np, p//'fy')
      nz = max(0_ip, a%np - 1)
      call same(a%mat, b%mat, nz, p//'mat')
      call same(a%cons, b%cons, nz, p//'cons')
      call same(a%sxx0, b%sxx0, nz, p//'sxx0')
      call same(a%sxy0, b%sxy0, nz, p//'sxy0')
      call compare_zones(a%zn, b%zn, p//'zn%')
   end subroutine compare_ffield

   subroutine compare_thermal(a, b, p)
      type(thermal_t), intent(in) :: a, b
      character(len=*), intent(in) :: p
      call same(a%time, b%time, p//'time')
      call same(a%nsteps, b%nsteps, p//'nsteps')
      call same(a%dt_user, b%dt_user, p//'dt_user')
      call same(a%age, b%age, p//'age')
      call same(a%age_test, b%age_test, p//'age_test')
      call same(a%temp_limit, b%temp_limit, p//'temp_limit')
      call same(a%step_limit, b%step_limit, p//'step_limit')
      call same(a%tol, b%tol, p//'tol')
      call same(a%nther, b%nther, p//'nther')
      call same(a%nmech, b%nmech, p//'nmech')
      call same(a%dt_last, b%dt_last, p//'dt_last')
      call same(a%ng, b%ng, p//'ng')
      if (a%ng == b%ng) then
         call same(a%temp, b%temp, a%ng, p//'temp')
         call same(a%fixed, b%fixed, a%ng, p//'fixed')
         call same(a%dtacc, b%dtacc, a%ng, p//'dtacc')
      end if
      call same(a%nc, b%nc, p//'nc')
      if (a%nc == b%nc) then
         call same(a%ctemp, b%ctemp, a%nc, p//'ctemp')
         call same(a%cfixed, b%cfixed, a%nc, p//'cfixed')
         call same(a%cdtacc, b%cdtacc, a%nc, p//'cdtacc')
      end if
      call same(a%nb, b%nb, p//'nb')
      if (a%nb == b%nb) then
         call same(a%btemp, b%btemp, a%nb, p//'btemp')
         call same(a%bfixed, b%bfixed, a%nb, p//'bfixed')
         call same(a%bdtacc, b%bdtacc, a%nb, p//'bdtacc')
      end if
      call same(a%nrec, b%nrec, p//'nrec')
      call same(a%nset, b%nset, p//'nset')
      if (a%nrec == b%nrec) then
         call same(a%rec_kind, b%rec_kind, a%nrec, p//'rec_kind')
         call same(a%rec_id, b%rec_id, a%nrec, p//'rec_id')
         call same(a%rec_p1, b%rec_p1, a%nrec, p//'rec_p1')
         call same(a%rec_p2, b%rec_p2, a%nrec, p//'rec_p2')
         call same(a%rec_t0, b%rec_t0, a%nrec, p//'rec_t0')
         call same(a%rec_set, b%rec_set, a%nrec, p//'rec_set')
      end if
      call same(a%nthis, b%nthis, p//'nthis')
      call same(a%ntcyc, b%ntcyc, p//'ntcyc')
      call same(a%this_type, b%this_type, p//'this_type')
      if (a%nthis == b%nthis) then
         call same(a%this_gp, b%this_gp, a%nthis, p//'this_gp')
         call same(a%this_x, b%this_x, a%nthis, p//'this_x')
         call same(a%this_y, b%this_y, a%nthis, p//'this_y')
         call same(a%this_kind, b%this_kind, a%nthis, p//'this_kind')
      end if
      call same(a%nsamp, b%nsamp, p//'nsamp')
      if (a%nsamp == b%nsamp) then
         call same(a%samp_time, b%samp_time, a%nsamp, p//'samp_time')
         call same(a%samp_val, b%samp_val, a%nsamp*20_ip, p//'samp_val')
      end if
   end subroutine compare_thermal

   subroutine compare_structures(a, b, p)
      type(structure_t), intent(in) :: a, b
      character(len=*), intent(in) :: p
      call same(a%nodes%n, b%nodes%n, p//'nodes%n')
      if (a%nodes%n == b%nodes%n) then
         associate (x => a%nodes, y => b%nodes, n => a%nodes%n, q => p//'nodes%')
            call same(x%x, y%x, n, q//'x'); call same(x%y, y%y, n, q//'y')
            call same(x%vx, y%vx, n, q//'vx'); call same(x%vy, y%vy, n, q//'vy')
            call same(x%vr, y%vr, n, q//'vr')
            call same(x%ux, y%ux, n, q//'ux'); call same(x%uy, y%uy, n, q//'uy')
            call same(x%rot, y%rot, n, q//'rot')
            call same(x%fx, y%fx, n, q//'fx'); call same(x%fy, y%fy, n, q//'fy')
            call same(x%fm, y%fm, n, q//'fm')
            call same(x%mass, y%mass, n, q//'mass'); call same(x%inertia, y%inertia, n, q//'inertia')
            call same(x%lx, y%lx, n, q//'lx'); call same(x%ly, y%ly, n, q//'ly')
            call same(x%fix, y%fix, n, q//'fix'); call same(x%material, y%material, n, q//'material')
         end associate
      end if
      call same(a%elements%n, b%elements%n, p//'elements%n')
      if (a%elements%n == b%elements%n) then
         associate (x => a%elements, y => b%elements, n => a%elements%n, q => p//'elements%')
            call same(x%n1, y%n1, n, q//'n1'); call same(x%n2, y%n2, n, q//'n2')
            call same(x%material, y%material, n, q//'material')
            call same(x%thick, y%thick, n, q//'thick')
            call same(x%length0, y%length0, n, q//'length0')
            call same(x%angle0, y%angle0, n, q//'angle0')
            call same(x%young, y%young, n, q//'young'); call same(x%area, y%area, n, q//'area')
            call same(x%inertia, y%inertia, n, q//'inertia')
            call same(x%axial, y%axial, n, q//'axial'); call same(x%shear, y%shear, n, q//'shear')
            call same(x%m1, y%m1, n, q//'m1'); call same(x%m2, y%m2, n, q//'m2')
         end associate
      end if
      call same(a%interfaces%n, b%interfaces%n, p//'interfaces%n')
      if (a%interfaces%n == b%interfaces%n) then
         associate (x => a%interfaces, y => b%interfaces, n => a%interfaces%n, &
                    q => p//'interfaces%')
            call same(x%node, y%node, n, q//'node'); call same(x%block, y%block, n, q//'block')
            call same(x%edge, y%edge, n, q//'edge')
            call same(x%material, y%material, n, q//'material')
            call same(x%x, y%x, n, q//'x'); call same(x%y, y%y, n, q//'y')
            call same(x%nx, y%nx, n, q//'nx'); call same(x%ny, y%ny, n, q//'ny')
            call same(x%un, y%un, n, q//'un'); call same(x%us, y%us, n, q//'us')
            call same(x%fn, y%fn, n, q//'fn'); call same(x%fs, y%fs, n, q//'fs')
            call same(x%flags, y%flags, n, q//'flags')
         end associate
      end if
   end subroutine compare_structures

   subroutine compare_reinforcement(a, b, p)
      type(reinforcement_t), intent(in) :: a, b
      character(len=*), intent(in) :: p
      call same(a%ncable, b%ncable, p//'ncable')
      call same(a%reinf%n, b%reinf%n, p//'reinf%n')
      if (a%reinf%n == b%reinf%n) then
         associate (x => a%reinf, y => b%reinf, n => a%reinf%n, q => p//'reinf%')
            call same(x%material, y%material, n, q//'material')
            call same(x%block1, y%block1, n, q//'block1'); call same(x%block2, y%block2, n, q//'block2')
            call same(x%g1a, y%g1a, n, q//'g1a'); call same(x%g1b, y%g1b, n, q//'g1b')
            call same(x%g2a, y%g2a, n, q//'g2a'); call same(x%g2b, y%g2b, n, q//'g2b')
            call same(x%w1, y%w1, n, q//'w1'); call same(x%w2, y%w2, n, q//'w2')
            call same(x%x1, y%x1, n, q//'x1'); call same(x%y1, y%y1, n, q//'y1')
            call same(x%x2, y%x2, n, q//'x2'); call same(x%y2, y%y2, n, q//'y2')
            call same(x%ax, y%ax, n, q//'ax'); call same(x%ay, y%ay, n, q//'ay')
            call same(x%tx, y%tx, n, q//'tx'); call same(x%ty, y%ty, n, q//'ty')
            call same(x%dx, y%dx, n, q//'dx'); call same(x%dy, y%dy, n, q//'dy')
            call same(x%uaxial, y%uaxial, n, q//'uaxial')
            call same(x%fa, y%fa, n, q//'fa'); call same(x%fs, y%fs, n, q//'fs')
            call same(x%fjs, y%fjs, n, q//'fjs'); call same(x%fjn, y%fjn, n, q//'fjn')
         end associate
      end if
      call same(a%nodes%n, b%nodes%n, p//'nodes%n')
      if (a%nodes%n == b%nodes%n) then
         associate (x => a%nodes, y => b%nodes, n => a%nodes%n, q => p//'nodes%')
            call same(x%cable, y%cable, n, q//'cable'); call same(x%block, y%block, n, q//'block')
            call same(x%zone, y%zone, n, q//'zone'); call same(x%matg, y%matg, n, q//'matg')
            call same(x%w1, y%w1, n, q//'w1'); call same(x%w2, y%w2, n, q//'w2')
            call same(x%w3, y%w3, n, q//'w3')
            call same(x%x, y%x, n, q//'x'); call same(x%y, y%y, n, q//'y')
            call same(x%hx, y%hx, n, q//'hx'); call same(x%hy, y%hy, n, q//'hy')
            call same(x%vs, y%vs, n, q//'vs'); call same(x%vx, y%vx, n, q//'vx')
            call same(x%vy, y%vy, n, q//'vy'); call same(x%fx, y%fx, n, q//'fx')
            call same(x%fy, y%fy, n, q//'fy'); call same(x%fg, y%fg, n, q//'fg')
            call same(x%slip, y%slip, n, q//'slip'); call same(x%glen, y%glen, n, q//'glen')
            call same(x%mass, y%mass, n, q//'mass')
         end associate
      end if
      call same(a%elements%n, b%elements%n, p//'elements%n')
      if (a%elements%n == b%elements%n) then
         associate (x => a%elements, y => b%elements, n => a%elements%n, q => p//'elements%')
            call same(x%cable, y%cable, n, q//'cable'); call same(x%n1, y%n1, n, q//'n1')
            call same(x%n2, y%n2, n, q//'n2'); call same(x%mats, y%mats, n, q//'mats')
            call same(x%area, y%area, n, q//'area'); call same(x%length0, y%length0, n, q//'length0')
            call same(x%length, y%length, n, q//'length'); call same(x%axial, y%axial, n, q//'axial')
            call same(x%pre, y%pre, n, q//'pre')
         end associate
      end if
   end subroutine compare_reinforcement


   subroutine compare_fluid(a, b, p)
      type(fluid_t), intent(in) :: a, b
      character(len=*), intent(in) :: p
      call same(a%rhow, b%rhow, p//'rhow')
      call same(a%bulkw, b%bulkw, p//'bulkw')
      call same(a%cohw, b%cohw, p//'cohw')
      call same(a%capratio, b%capratio, p//'capratio')
      call same(a%sflow, b%sflow, p//'sflow')
      call same(a%eff, b%eff, p//'eff')
      call same(a%ywtab, b%ywtab, p//'ywtab')
      call same(a%ptol, b%ptol, p//'ptol')
      call same(a%nd, b%nd, p//'nd')
      call same(a%nc, b%nc, p//'nc')
      if (a%nd == b%nd) then
         call same(a%p, b%p, a%nd, p//'p')
         call same(a%fixed, b%fixed, a%nd, p//'fixed')
         call same(a%vol, b%vol, a%nd, p//'vol')
         call same(a%xd, b%xd, a%nd, p//'xd')
         call same(a%yd, b%yd, a%nd, p//'yd')
      end if
      if (a%nc == b%nc) then
         call same(a%aperture, b%aperture, a%nc, p//'aperture')
         call same(a%q, b%q, a%nc, p//'q')
         call same(a%bnd_code, b%bnd_code, a%nc, p//'bnd_code')
         call same(a%bnd_p, b%bnd_p, a%nc, p//'bnd_p')
         call same(a%bnd_g, b%bnd_g, a%nc, p//'bnd_g')
         call same(a%cdom1, b%cdom1, a%nc, p//'cdom1')
         call same(a%cdom2, b%cdom2, a%nc, p//'cdom2')
      end if
   end subroutine compare_fluid

   subroutine compare_be(a, b, p)
      type(be_t), intent(in) :: a, b
      character(len=*), intent(in) :: p
      call same(a%mat, b%mat, p//'mat')
      call same(a%half, b%half, p//'half')
      call same(a%fix, b%fix, p//'fix')
      call same(a%xh, b%xh, p//'xh')
      call same(a%yh, b%yh, p//'yh')
      call same(a%xv, b%xv, p//'xv')
      call same(a%yv, b%yv, p//'yv')
      call same(a%nc, b%nc, p//'nc')
      call same(a%ne, b%ne, p//'ne')
      call same(a%linked, b%linked, p//'linked')
      call same(a%g, b%g, p//'g')
      call same(a%nu, b%nu, p//'nu')
      if (a%nc == b%nc) then
         call same(a%corner, b%corner, a%nc, p//'corner')
         call same(a%x0, b%x0, a%nc, p//'x0')
         call same(a%y0, b%y0, a%nc, p//'y0')
      end if
      if (a%ne == b%ne) then
         call same(a%ea, b%ea, a%ne, p//'ea')
         call same(a%eb, b%eb, a%ne, p//'eb')
      end if
   end subroutine compare_be

   subroutine compare_boundary(a, b, p)
      type(boundary_t), intent(in) :: a, b
      character(len=*), intent(in) :: p
      integer :: t
      character(len=1) :: d
      call same(a%n, b%n, p//'n')
      call same(a%corners_seen, b%corners_seen, p//'corners_seen')
      call same(a%t_start, b%t_start, p//'t_start')
      do t = 1, 2
         write (d, '(i1)') t
         call compare_table(a%table(t), b%table(t), p//'table('//d//')%')
      end do
      if (a%n /= b%n) return
      call same(a%corner, b%corner, a%n, p//'corner')
      call same(a%ix, b%ix, a%n, p//'ix')
      call same(a%iy, b%iy, a%n, p//'iy')
      call same(a%fx, b%fx, a%n, p//'fx')
      call same(a%fy, b%fy, a%n, p//'fy')
      call same(a%dfx, b%dfx, a%n, p//'dfx')
      call same(a%dfy, b%dfy, a%n, p//'dfy')
      call same(a%hx, b%hx, a%n, p//'hx')
      call same(a%hy, b%hy, a%n, p//'hy')
      call same(a%freqx, b%freqx, a%n, p//'freqx')
      call same(a%tloadx, b%tloadx, a%n, p//'tloadx')
      call same(a%freqy, b%freqy, a%n, p//'freqy')
      call same(a%tloady, b%tloady, a%n, p//'tloady')
      call same(a%xmul, b%xmul, a%n, p//'xmul')
      call same(a%ymul, b%ymul, a%n, p//'ymul')
      call same(a%vx, b%vx, a%n, p//'vx')
      call same(a%vy, b%vy, a%n, p//'vy')
      call same(a%vis, b%vis, a%n, p//'vis')
      call same(a%vmat, b%vmat, a%n, p//'vmat')
      call same(a%ff, b%ff, a%n, p//'ff')
      call same(a%fup, b%fup, p//'fup')
      call same(a%sxx_prev, b%sxx_prev, a%n, p//'sxx_prev')
      call same(a%sxy_prev, b%sxy_prev, a%n, p//'sxy_prev')
      call same(a%syy_prev, b%syy_prev, a%n, p//'syy_prev')
      call same(a%sxx_next, b%sxx_next, a%n, p//'sxx_next')
      call same(a%sxy_next, b%sxy_next, a%n, p//'sxy_next')
      call same(a%syy_next, b%syy_next, a%n, p//'syy_next')
      call same(a%dsxx_prev, b%dsxx_prev, a%n, p//'dsxx_prev')
      call same(a%dsxy_prev, b%dsxy_prev, a%n, p//'dsxy_prev')
      call same(a%dsyy_prev, b%dsyy_prev, a%n, p//'dsyy_prev')
      call same(a%dsxx_next, b%dsxx_next, a%n, p//'dsxx_next')
      call same(a%dsxy_next, b%dsxy_next, a%n, p//'dsxy_next')
      call same(a%dsyy_next, b%dsyy_next, a%n, p//'dsyy_next')
      call same(a%end_prev, b%end_prev, a%n, p//'end_prev')
      call same(a%end_next, b%end_next, a%n, p//'end_next')
      call compare_zpress(a%zp, b%zp, p//'zp%')
   end subroutine compare_boundary

   subroutine compare_zpress(a, b, p)
      type(zpress_t), intent(in) :: a, b
      character(len=*), intent(in) :: p
      call same(a%n, b%n, p//'n')
      call same(a%h_next, b%h_next, p//'h_next')
      call same(a%freq_next, b%freq_next, p//'freq_next')
      call same(a%tload_next, b%tload_next, p//'tload_next')
      call same(a%nz, b%nz, p//'nz')
      if (a%n == b%n) then
         call same(a%x, b%x, a%n, p//'x')
         call same(a%y, b%y, a%n, p//'y')
         call same(a%rad, b%rad, a%n, p//'rad')
         call same(a%pz, b%pz, a%n, p//'pz')
         call same(a%h, b%h, a%n, p//'h')
         call same(a%freq, b%freq, a%n, p//'freq')
         call same(a%tload, b%tload, a%n, p//'tload')
         call same(a%nzone, b%nzone, a%n, p//'nzone')
      end if
      if (a%nz == b%nz) then
         call same(a%zone, b%zone, a%nz, p//'zone')
         call same(a%src, b%src, a%nz, p//'src')
      end if
   end subroutine compare_zpress

   subroutine compare_table(a, b, p)
      type(boundary_table_t), intent(in) :: a, b
      character(len=*), intent(in) :: p
      character(len=:), allocatable :: ha, hb
      ! an unset heading is saved as '' (stream_text)
      ha = ''
      hb = ''
      if (allocated(a%heading)) ha = a%heading
      if (allocated(b%heading)) hb = b%heading
      call same(ha, hb, p//'heading')
      call same(a%np, b%np, p//'np')
      call same(a%dt, b%dt, p//'dt')
      call same(a%values, b%values, a%np, p//'values')
   end subroutine compare_table

   subroutine compare_geometry(a, b, p)
      type(geometry_t), intent(in) :: a, b
      character(len=*), intent(in) :: p
      integer :: i
      call same(a%round, b%round, p//'round')
      call same(a%edge_min, b%edge_min, p//'edge_min')
      call same(a%edge_set, b%edge_set, p//'edge_set')
      call same(a%tol, b%tol, p//'tol')
      call same(a%extent, b%extent, p//'extent')
      call same(a%original_area, b%original_area, p//'original_area')
      call same(a%deleted_area, b%deleted_area, p//'deleted_area')
      call same(a%block_created, b%block_created, p//'block_created')
      call same(a%has_jregion, b%has_jregion, p//'has_jregion')
      call same(a%jregion_x, b%jregion_x, p//'jregion_x')
      call same(a%jregion_y, b%jregion_y, p//'jregion_y')
      call same(a%rng_state, b%rng_state, p//'rng_state')
      call same(a%jmat_default, b%jmat_default, p//'jmat_default')
      call same(a%jcons_default, b%jcons_default, p//'jcons_default')
      call same(a%contacts_valid, b%contacts_valid, p//'contacts_valid')
      call same(a%domains_valid, b%domains_valid, p//'domains_valid')
      call same(a%outer_domain, b%outer_domain, p//'outer_domain')
      call same(a%ia%mfree, b%ia%mfree, p//'ia%mfree')
      call same(a%ia%outer, b%ia%outer, p//'ia%outer')
      call same(a%ia%njunk, b%ia%njunk, p//'ia%njunk')
      if (a%ia%njunk == b%ia%njunk .and. a%ia%njunk > 0) then
         call same(a%ia%junk_addr, b%ia%junk_addr, a%ia%njunk, p//'ia%junk_addr')
         call same(a%ia%junk_len, b%ia%junk_len, a%ia%njunk, p//'ia%junk_len')
      end if
      do i = 1, size(a%cut_stats)
         call same(a%cut_stats(i), b%cut_stats(i), p//'cut_stats')
      end do
      call same(a%nrefused_keys, b%nrefused_keys, p//'nrefused_keys')
      if (a%nrefused_keys == b%nrefused_keys) &
         call same(a%refused_keys, b%refused_keys, a%nrefused_keys, p//'refused_keys')
      call same(a%mechanical, b%mechanical, p//'mechanical')
      call compare_blocks(a%blocks, b%blocks, p//'blocks%')
      call compare_corners(a%corners, b%corners, p//'corners%')
      call compare_contacts(a%contacts, b%contacts, p//'contacts%')
      call compare_domains(a%domains, b%domains, p//'domains%')
      call compare_pending(a%pending, b%pending, p//'pending%')
      call compare_tunnels(a%tunnels, b%tunnels, p//'tunnels%')
      call compare_jplot(a%jplot, b%jplot, p//'jplot%')
      call compare_gridpoints(a%gridpoints, b%gridpoints, p//'gridpoints%')
      call compare_zones(a%zones, b%zones, p//'zones%')
   end subroutine compare_geometry

   subroutine compare_gridpoints(a, b, p)
      type(gridpoint_list_t), intent(in) :: a, b
      character(len=*), intent(in) :: p
      call same(a%n, b%n, p//'n')
      if (a%n /= b%n) return
      call same(a%live, b%live, a%n, p//'live')
      call same(a%block, b%block, a%n, p//'block')
      call same(a%corner, b%corner, a%n, p//'corner')
      call same(a%x, b%x, a%n, p//'x')
      call same(a%y, b%y, a%n, p//'y')
      call same(a%vx, b%vx, a%n, p//'vx')
      call same(a%vy, b%vy, a%n, p//'vy')
      call same(a%ux, b%ux, a%n, p//'ux')
      call same(a%uy, b%uy, a%n, p//'uy')
      call same(a%fx, b%fx, a%n, p//'fx')
      call same(a%fy, b%fy, a%n, p//'fy')
      call same(a%mass, b%mass, a%n, p//'mass')
      call same(a%vfix, b%vfix, a%n, p//'vfix')
      call same(a%addr, b%addr, a%n, p//'addr')
   end subroutine compare_gridpoints

   subroutine compare_zones(a, b, p)
      type(zone_list_t), intent(in) :: a, b
      character(len=*), intent(in) :: p
      call same(a%n, b%n, p//'n')
      if (a%n /= b%n) return
      call same(a%live, b%live, a%n, p//'live')
      call same(a%block, b%block, a%n, p//'block')
      call same(a%g1, b%g1, a%n, p//'g1')
      call same(a%g2, b%g2, a%n, p//'g2')
      call same(a%g3, b%g3, a%n, p//'g3')
      call same(a%sxx, b%sxx, a%n, p//'sxx')
      call same(a%sxy, b%sxy, a%n, p//'sxy')
      call same(a%syy, b%syy, a%n, p//'syy')
      call same(a%szz, b%szz, a%n, p//'szz')
      call same(a%state, b%state, a%n, p//'state')
      call same(a%addr, b%addr, a%n, p//'addr')
   end subroutine compare_zones

   subroutine compare_blocks(a, b, p)
      type(block_list_t), intent(in) :: a, b
      character(len=*), intent(in) :: p
      call same(a%n, b%n, p//'n')
      if (a%n /= b%n) return
      call same(a%live, b%live, a%n, p//'live')
      call same(a%first_corner, b%first_corner, a%n, p//'first_corner')
      call same(a%ncorner, b%ncorner, a%n, p//'ncorner')
      call same(a%material, b%material, a%n, p//'material')
      call same(a%cons, b%cons, a%n, p//'cons')
      call same(a%area, b%area, a%n, p//'area')
      call same(a%xc, b%xc, a%n, p//'xc')
      call same(a%yc, b%yc, a%n, p//'yc')
      call same(a%xmin, b%xmin, a%n, p//'xmin')
      call same(a%xmax, b%xmax, a%n, p//'xmax')
      call same(a%ymin, b%ymin, a%n, p//'ymin')
      call same(a%ymax, b%ymax, a%n, p//'ymax')
      call same(a%mass, b%mass, a%n, p//'mass')
      call same(a%inertia, b%inertia, a%n, p//'inertia')
      call same(a%vx, b%vx, a%n, p//'vx')
      call same(a%vy, b%vy, a%n, p//'vy')
      call same(a%vr, b%vr, a%n, p//'vr')
      call same(a%ux, b%ux, a%n, p//'ux')
      call same(a%uy, b%uy, a%n, p//'uy')
      call same(a%rot, b%rot, a%n, p//'rot')
      call same(a%fx, b%fx, a%n, p//'fx')
      call same(a%fy, b%fy, a%n, p//'fy')
      call same(a%fm, b%fm, a%n, p//'fm')
      call same(a%lx, b%lx, a%n, p//'lx')
      call same(a%ly, b%ly, a%n, p//'ly')
      call same(a%fixed, b%fixed, a%n, p//'fixed')
      call same(a%fdef, b%fdef, a%n, p//'fdef')
      call same(a%zfirst, b%zfirst, a%n, p//'zfirst')
      call same(a%nzone, b%nzone, a%n, p//'nzone')
      call same(a%gfirst, b%gfirst, a%n, p//'gfirst')
      call same(a%ngp, b%ngp, a%n, p//'ngp')
      call same(a%addr, b%addr, a%n, p//'addr')
      call same(a%sdef, b%sdef, a%n, p//'sdef')
      call same(a%exx, b%exx, a%n, p//'exx')
      call same(a%eyy, b%eyy, a%n, p//'eyy')
      call same(a%exy, b%exy, a%n, p//'exy')
      call same(a%dxx, b%dxx, a%n, p//'dxx')
      call same(a%dyy, b%dyy, a%n, p//'dyy')
      call same(a%dxy, b%dxy, a%n, p//'dxy')
      call same(a%sxx, b%sxx, a%n, p//'sxx')
      call same(a%syy, b%syy, a%n, p//'syy')
      call same(a%sxy, b%sxy, a%n, p//'sxy')
      call same(a%qxx, b%qxx, a%n, p//'qxx')
      call same(a%qyy, b%qyy, a%n, p//'qyy')
      call same(a%qxy, b%qxy, a%n, p//'qxy')
      call same(a%bstate, b%bstate, a%n, p//'bstate')
   end subroutine compare_blocks

   subroutine compare_corners(a, b, p)
      type(corner_list_t), intent(in) :: a, b
      character(len=*), intent(in) :: p
      call same(a%n, b%n, p//'n')
      if (a%n /= b%n) return
      call same(a%live, b%live, a%n, p//'live')
      call same(a%x, b%x, a%n, p//'x')
      call same(a%y, b%y, a%n, p//'y')
      call same(a%block, b%block, a%n, p//'block')
      call same(a%next, b%next, a%n, p//'next')
      call same(a%prev, b%prev, a%n, p//'prev')
      call same(a%rx, b%rx, a%n, p//'rx')
      call same(a%ry, b%ry, a%n, p//'ry')
      call same(a%radius, b%radius, a%n, p//'radius')
      call same(a%ux, b%ux, a%n, p//'ux')
      call same(a%uy, b%uy, a%n, p//'uy')
      call same(a%gp, b%gp, a%n, p//'gp')
      call same(a%addr, b%addr, a%n, p//'addr')
   end subroutine compare_corners

   subroutine compare_contacts(a, b, p)
      type(contact_list_t), intent(in) :: a, b
      character(len=*), intent(in) :: p
      call same(a%n, b%n, p//'n')
      if (a%n /= b%n) return
      call same(a%live, b%live, a%n, p//'live')
      call same(a%block1, b%block1, a%n, p//'block1')
      call same(a%block2, b%block2, a%n, p//'block2')
      call same(a%kind, b%kind, a%n, p//'kind')
      call same(a%end1, b%end1, a%n, p//'end1')
      call same(a%end2, b%end2, a%n, p//'end2')
      call same(a%jmat, b%jmat, a%n, p//'jmat')
      call same(a%jcons, b%jcons, a%n, p//'jcons')
      call same(a%dom1, b%dom1, a%n, p//'dom1')
      call same(a%dom2, b%dom2, a%n, p//'dom2')
      call same(a%x, b%x, a%n, p//'x')
      call same(a%y, b%y, a%n, p//'y')
      call same(a%nx, b%nx, a%n, p//'nx')
      call same(a%ny, b%ny, a%n, p//'ny')
      call same(a%length, b%length, a%n, p//'length')
      call same(a%gap, b%gap, a%n, p//'gap')
      call compare_joint_state(a%state, b%state, a%n, p//'state%')
      call same(a%addr, b%addr, a%n, p//'addr')
   end subroutine compare_contacts

   subroutine compare_joint_state(a, b, n, p)
      type(joint_state_t), intent(in) :: a, b
      integer(ip), intent(in) :: n
      character(len=*), intent(in) :: p
      call same(a%fn, b%fn, n, p//'fn')
      call same(a%fs, b%fs, n, p//'fs')
      call same(a%un, b%un, n, p//'un')
      call same(a%us, b%us, n, p//'us')
      call same(a%flags, b%flags, n, p//'flags')
      call same(a%ud, b%ud, n, p//'ud')
      call same(a%phi_eff, b%phi_eff, n, p//'phi_eff')
      call same(a%reversal, b%reversal, n, p//'reversal')
      call same(a%dus_old, b%dus_old, n, p//'dus_old')
   end subroutine compare_joint_state

   subroutine compare_domains(a, b, p)
      type(domain_list_t), intent(in) :: a, b
      character(len=*), intent(in) :: p
      call same(a%n, b%n, p//'n')
      call same(a%nring, b%nring, p//'nring')
      if (a%n /= b%n .or. a%nring /= b%nring) return
      call same(a%live, b%live, a%n, p//'live')
      call same(a%outer, b%outer, a%n, p//'outer')
      call same(a%area, b%area, a%n, p//'area')
      call same(a%first, b%first, a%n, p//'first')
      call same(a%addr, b%addr, a%n, p//'addr')
      call same(a%count, b%count, a%n, p//'count')
      call same(a%ring, b%ring, a%nring, p//'ring')
   end subroutine compare_domains

   subroutine compare_pending(a, b, p)
      type(pending_list_t), intent(in) :: a, b
      character(len=*), intent(in) :: p
      call same(a%n, b%n, p//'n')
      if (a%n /= b%n) return
      call same(a%x1, b%x1, a%n, p//'x1')
      call same(a%y1, b%y1, a%n, p//'y1')
      call same(a%x2, b%x2, a%n, p//'x2')
      call same(a%y2, b%y2, a%n, p//'y2')
   end subroutine compare_pending

   subroutine compare_tunnels(a, b, p)
      type(tunnel_list_t), intent(in) :: a, b
      character(len=*), intent(in) :: p
      call same(a%n, b%n, p//'n')
      if (a%n /= b%n) return
      call same(a%xc, b%xc, a%n, p//'xc')
      call same(a%yc, b%yc, a%n, p//'yc')
      call same(a%r, b%r, a%n, p//'r')
      call same(a%nside, b%nside, a%n, p//'nside')
   end subroutine compare_tunnels

   subroutine compare_jplot(a, b, p)
      type(jplot_list_t), intent(in) :: a, b
      character(len=*), intent(in) :: p
      call same(a%on, b%on, p//'on')
      call same(a%n, b%n, p//'n')
      if (a%n /= b%n) return
      call same(a%x1, b%x1, a%n, p//'x1')
      call same(a%y1, b%y1, a%n, p//'y1')
      call same(a%x2, b%x2, a%n, p//'x2')
      call same(a%y2, b%y2, a%n, p//'y2')
      call same(a%block, b%block, a%n, p//'block')
   end subroutine compare_jplot

   subroutine compare_mechanics(a, b, p)
      type(mechanics_t), intent(in) :: a, b
      character(len=*), intent(in) :: p
      integer :: k
      call same(a%time, b%time, p//'time')
      call same(a%step, b%step, p//'step')
      call same(a%dt, b%dt, p//'dt')
      call same(a%frac_block, b%frac_block, p//'frac_block')
      call same(a%frac_zone, b%frac_zone, p//'frac_zone')
      call same(a%frac_fluid, b%frac_fluid, p//'frac_fluid')
      call same(a%damping, b%damping, p//'damping')
      call same(a%auto_fac, b%auto_fac, p//'auto_fac')
      call same(a%auto_mult1, b%auto_mult1, p//'auto_mult1')
      call same(a%auto_mult2, b%auto_mult2, p//'auto_mult2')
      call same(a%auto_alpha, b%auto_alpha, p//'auto_alpha')
      call same(a%local_alpha, b%local_alpha, p//'local_alpha')
      call same(a%kinetic_old, b%kinetic_old, p//'kinetic_old')
      call same(a%rayleigh_fcrit, b%rayleigh_fcrit, p//'rayleigh_fcrit')
      call same(a%rayleigh_freq, b%rayleigh_freq, p//'rayleigh_freq')
      call same(a%rayleigh_mass, b%rayleigh_mass, p//'rayleigh_mass')
      call same(a%rayleigh_stiff, b%rayleigh_stiff, p//'rayleigh_stiff')
      call same(a%internal_fcrit, b%internal_fcrit, p//'internal_fcrit')
      call same(a%internal_freq, b%internal_freq, p//'internal_freq')
      call same(a%internal_mass, b%internal_mass, p//'internal_mass')
      call same(a%internal_stiff, b%internal_stiff, p//'internal_stiff')
      call same(a%mscale, b%mscale, p//'mscale')
      call same(a%mscale_zone, b%mscale_zone, p//'mscale_zone')
      call same(a%mscale_block, b%mscale_block, p//'mscale_block')
      call same(a%mscale_part, b%mscale_part, p//'mscale_part')
      call same(a%mscale_tdel, b%mscale_tdel, p//'mscale_tdel')
      call same(a%nupcon, b%nupcon, p//'nupcon')
      call same(a%dscan, b%dscan, p//'dscan')
      call same(a%cscan, b%cscan, p//'cscan')
      call same(a%ovtol, b%ovtol, p//'ovtol')
      call same(a%clemin, b%clemin, p//'clemin')
      call same(a%clemin_auto, b%clemin_auto, p//'clemin_auto')
      call same(a%motion_since_scan, b%motion_since_scan, p//'motion_since_scan')
      call same(a%unbalanced, b%unbalanced, p//'unbalanced')
      call same(a%masses_valid, b%masses_valid, p//'masses_valid')
      call same(a%fxhis, b%fxhis, p//'fxhis')
      call same(a%fyhis, b%fyhis, p//'fyhis')
      call same(a%search_current, b%search_current, p//'search_current')
      do k = 1, 3
         call same(a%search_sizes(k), b%search_sizes(k), p//'search_sizes')
      end do
      call same(a%search_margin, b%search_margin, p//'search_margin')
      call same(a%probe_time, b%probe_time, p//'probe_time')
      call same(a%probe_w, b%probe_w, p//'probe_w')
      call same(a%probe_wref, b%probe_wref, p//'probe_wref')
   end subroutine compare_mechanics

   subroutine compare_history(a, b, p)
      type(history_t), intent(in) :: a, b
      character(len=*), intent(in) :: p
      call same(a%n, b%n, p//'n')
      call same(a%nsample, b%nsample, p//'nsample')
      call same(a%ncyc, b%ncyc, p//'ncyc')
      call same(a%typed, b%typed, p//'typed')
      if (a%n /= b%n .or. a%nsample /= b%nsample) return
      call same(a%kind, b%kind, a%n, p//'kind')
      call same(a%entity, b%entity, a%n, p//'entity')
      call same(a%x, b%x, a%n, p//'x')
      call same(a%y, b%y, a%n, p//'y')
      call same(a%px, b%px, a%n, p//'px')
      call same(a%py, b%py, a%n, p//'py')
      call same(a%time, b%time, a%nsample, p//'time')
      call same(a%step, b%step, a%nsample, p//'step')
      call same(a%values, b%values, a%nsample, p//'values')
      call same(a%first_sample, b%first_sample, a%n, p//'first_sample')
   end subroutine compare_history

   ! Reals are compared as bit patterns: exact, and -0.0 differs from 0.0.
   subroutine same_real(a, b, label)
      real(wp), intent(in) :: a, b
      character(len=*), intent(in) :: label
      call check(transfer(a, 0_i8) == transfer(b, 0_i8), label)
   end subroutine same_real

   subroutine same_reals(a, b, label)
      real(wp), intent(in) :: a(:), b(:)
      character(len=*), intent(in) :: label
      call check(size(a) == size(b), label//' (size)')
      if (size(a) /= size(b)) return
      call check(all(transfer(a, 0_i8, size(a)) == transfer(b, 0_i8, size(b))), label)
   end subroutine same_reals

   subroutine same_int(a, b, label)
      integer, intent(in) :: a, b
      character(len=*), intent(in) :: label
      call check(a == b, label)
   end subroutine same_int

   subroutine same_i8(a, b, label)
      integer(i8), intent(in) :: a, b
      character(len=*), intent(in) :: label
      call check(a == b, label)
   end subroutine same_i8

   subroutine same_log(a, b, label)
      logical, intent(in) :: a, b
      character(len=*), intent(in) :: label
      call check(a .eqv. b, label)
   end subroutine same_log

   subroutine same_text(a, b, label)
      character(len=:), allocatable, intent(in) :: a, b
      character(len=*), intent(in) :: label
      call check(allocated(a) .eqv. allocated(b), label//' (allocation)')
      if (.not. (allocated(a) .and. allocated(b))) return
      call check(len(a) == len(b) .and. a == b, label)
   end subroutine same_text

   !> Lists: allocation status, capacity, entries 1..n.
   subroutine same_real_list(a, b, n, label)
      real(wp), allocatable, intent(in) :: a(:), b(:)
      integer(ip), intent(in) :: n
      character(len=*), intent(in) :: label
      if (.not. same_allocation(allocated(a), allocated(b), label)) return
      call check(size(a) == size(b), label//' (capacity)')
      if (size(b) < n) return
      call same_reals(a(1:n), b(1:n), label)
   end subroutine same_real_list

   subroutine same_int_list(a, b, n, label)
      integer, allocatable, intent(in) :: a(:), b(:)
      integer(ip), intent(in) :: n
      character(len=*), intent(in) :: label
      if (.not. same_allocation(allocated(a), allocated(b), label)) return
      call check(size(a) == size(b), label//' (capacity)')
      if (size(b) < n) return
      call check(all(a(1:n) == b(1:n)), label)
   end subroutine same_int_list

   subroutine same_code_list(a, b, n, label)
      integer(i1), allocatable, intent(in) :: a(:), b(:)
      integer(ip), intent(in) :: n
      character(len=*), intent(in) :: label
      if (.not. same_allocation(allocated(a), allocated(b), label)) return
      call check(size(a) == size(b), label//' (capacity)')
      if (size(b) < n) return
      call check(all(a(1:n) == b(1:n)), label)
   end subroutine same_code_list

   subroutine same_log_list(a, b, n, label)
      logical, allocatable, intent(in) :: a(:), b(:)
      integer(ip), intent(in) :: n
      character(len=*), intent(in) :: label
      if (.not. same_allocation(allocated(a), allocated(b), label)) return
      call check(size(a) == size(b), label//' (capacity)')
      if (size(b) < n) return
      call check(all(a(1:n) .eqv. b(1:n)), label)
   end subroutine same_log_list

   !> One-byte logicals, compared as default ones (same_log_list).
   subroutine same_log1_list(a, b, n, label)
      logical(l1), allocatable, intent(in) :: a(:), b(:)
      integer(ip), intent(in) :: n
      character(len=*), intent(in) :: label
      logical, allocatable :: da(:), db(:)
      if (allocated(a)) da = logical(a)
      if (allocated(b)) db = logical(b)
      call same_log_list(da, db, n, label)
   end subroutine same_log1_list

   !> Tables: columns 1..n.
   subroutine same_real_table(a, b, n, label)
      real(wp), allocatable, intent(in) :: a(:, :), b(:, :)
      integer(ip), intent(in) :: n
      character(len=*), intent(in) :: label
      integer(ip) :: j
      if (.not. same_allocation(allocated(a), allocated(b), label)) return
      call check(all(shape(a) == shape(b)), label//' (capacity)')
      if (any(shape(a) /= shape(b)) .or. size(b, 2) < n) return
      do j = 1, n
         call same_reals(a(:, j), b(:, j), label)
      end do
   end subroutine same_real_table

   subroutine same_log_table(a, b, n, label)
      logical, allocatable, intent(in) :: a(:, :), b(:, :)
      integer(ip), intent(in) :: n
      character(len=*), intent(in) :: label
      if (.not. same_allocation(allocated(a), allocated(b), label)) return
      call check(all(shape(a) == shape(b)), label//' (capacity)')
      if (any(shape(a) /= shape(b)) .or. size(b, 2) < n) return
      call check(all(a(:, 1:n) .eqv. b(:, 1:n)), label)
   end subroutine same_log_table

   logical function same_allocation(a, b, label) result(both)
      logical, intent(in) :: a, b
      character(len=*), intent(in) :: label
      call check(a .eqv. b, label//' (allocation)')
      both = a .and. b
   end function same_allocation

end module testing_model
