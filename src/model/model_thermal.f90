!> Heat conduction state (manual Section 7: THERMAL, INITEM, TFIX, TFREE, THAPP,
!> RUN, SET THDT / NTHER / NMECH).
!>
!> An allocatable component of model_t, created by THERMAL (or the first thermal
!> command); a model without it runs no thermal code.
!>
!> Per gridpoint (ids of geometry%gridpoints; the thermal mesh is the zoning of
!> the fully-deformable blocks, and per corner and block centroid for blocks
!> without zones, Fig. 7-4): temperature, fixed flag and the temperature
!> change accumulated since the thermal stresses were last applied (the
!> manual's kgdtm). THAPP conditions are kept as records: convection,
!> radiation and flux on block corners (applied along an edge whose two
!> consecutive corners both carry the condition, Section 7.4.1), volume
!> sources on blocks. Strengths decay as S = S0 exp(c (t - t0)).
module model_thermal
   use core_kinds, only: wp, ip
   use core_arrays, only: grow_array, grow_lists
   implicit none
   private
   public :: thermal_t, thermal_size, thermal_size_rigid, thermal_add_record, thermal_add_sample
   public :: max_thist
   public :: bc_convection, bc_flux, bc_radiation, bc_source

   !> THIST points at most (manual Section 7.4.1: "up to twenty points").
   integer, parameter :: max_thist = 20

   integer, parameter :: bc_convection = 1, bc_flux = 2, bc_radiation = 3, bc_source = 4

   type :: thermal_t
      ! RUN limits and settings (kept for later RUN commands, Section 7.4.1)
      real(wp) :: time = 0.0_wp            !< thermal time (age)
      integer(ip) :: nsteps = 0            !< thermal steps taken in total
      real(wp) :: dt_user = 0.0_wp         !< RUN DELT / SET THDT; 0: automatic
      real(wp) :: age = 0.0_wp             !< RUN AGE limit
      logical :: age_test = .false.        !< AGE given (NOAGE clears)
      real(wp) :: temp_limit = 20.0_wp     !< RUN TEMP: max change since mechanics
      integer(ip) :: step_limit = 500      !< RUN STEP
      real(wp) :: tol = 0.1_wp             !< RUN TOL: points merged within this distance
      integer(ip) :: nther = 0             !< SET NTHER
      integer(ip) :: nmech = 500           !< SET NMECH
      real(wp) :: dt_last = 0.0_wp         !< time step of the last RUN
      ! gridpoints
      integer(ip) :: ng = 0
      real(wp), allocatable :: temp(:)     !< temperature
      logical, allocatable :: fixed(:)     !< TFIX
      real(wp), allocatable :: dtacc(:)    !< change since thermal stresses were applied
      ! blocks without zones (rigid and SDEF; Section 7.5.2.1, Fig. 7-4: triangles
      ! from the centroid to the corners), schema 13: per corner and per block
      ! centroid the same three quantities (the manual's ktemp / kthpf / kdtem
      ! and kbtem / kbfix / kbdtm); used only while the block has no zones
      integer(ip) :: nc = 0, nb = 0
      real(wp), allocatable :: ctemp(:), cdtacc(:)   !< (nc) corner temperature, change
      logical, allocatable :: cfixed(:)              !< (nc) TFIX
      real(wp), allocatable :: btemp(:), bdtacc(:)   !< (nb) centroid temperature, change
      logical, allocatable :: bfixed(:)              !< (nb) TFIX
      ! THAPP records
      integer(ip) :: nrec = 0
      integer(ip), allocatable :: rec_kind(:)    !< bc_convection .. bc_source
      integer(ip), allocatable :: rec_id(:)      !< corner id (bc_source: block id)
      real(wp), allocatable :: rec_p1(:)         !< coefficient / initial strength
      real(wp), allocatable :: rec_p2(:)         !< medium temperature / decay constant
      real(wp), allocatable :: rec_t0(:)         !< thermal time when applied
      integer(ip), allocatable :: rec_set(:)     !< THAPP command serial number
      integer(ip) :: nset = 0                    !< THAPP commands given
      ! THIST: temperature histories at gridpoints, sampled every ntcyc steps
      integer(ip) :: nthis = 0
      integer(ip) :: ntcyc = 10
      integer(ip) :: this_type = 0               !< THIST TYPE n (shown while running)
      integer(ip), allocatable :: this_gp(:)     !< (max_thist) gridpoint of each history
                                                 !< (this_kind 1: corner, 2: block centroid)
      integer(ip), allocatable :: this_kind(:)   !< (max_thist) 0 gridpoint, 1 rigid
                                                 !< corner, 2 rigid block centroid (schema 13)
      real(wp), allocatable :: this_x(:), this_y(:)   !< (max_thist) requested point
      integer(ip) :: nsamp = 0
      real(wp), allocatable :: samp_time(:)      !< thermal time of each sample
      real(wp), allocatable :: samp_val(:)       !< value of history h in sample s at
                                                 !< (s - 1) max_thist + h
   end type thermal_t

contains

   !> Room for ng gridpoints (new ones: temperature 0, free).
   subroutine thermal_size(th, ng)
      type(thermal_t), intent(inout) :: th
      integer(ip), intent(in) :: ng
      call size_temperatures(th%ng, ng, th%temp, th%fixed, th%dtacc)
   end subroutine thermal_size

   !> Room for nc corners and nb blocks (blocks without zones; new ones:
   !> temperature 0, free).
   subroutine thermal_size_rigid(th, nc, nb)
      type(thermal_t), intent(inout) :: th
      integer(ip), intent(in) :: nc, nb
      call size_temperatures(th%nc, nc, th%ctemp, th%cfixed, th%cdtacc)
      call size_temperatures(th%nb, nb, th%btemp, th%bfixed, th%bdtacc)
   end subroutine thermal_size_rigid

   !> Room for `need` points of one temperature field (gridpoints, corners
   !> or blocks) that has n: new ones at temperature 0, free.
   subroutine size_temperatures(n, need, temp, fixed, dtacc)
      integer(ip), intent(inout) :: n
      integer(ip), intent(in) :: need
      real(wp), allocatable, intent(inout) :: temp(:), dtacc(:)
      logical, allocatable, intent(inout) :: fixed(:)
      integer(ip) :: m
      if (.not. allocated(temp)) allocate (temp(0), fixed(0), dtacc(0))
      if (need > size(temp)) then
         m = max(need, 2_ip*size(temp))
         call grow_lists(n, m, temp, dtacc)
         call grow_array(fixed, n, m)
      end if
      if (need > n) then
         temp(n + 1:need) = 0.0_wp
         fixed(n + 1:need) = .false.
         dtacc(n + 1:need) = 0.0_wp
         n = need
      end if
   end subroutine size_temperatures

   !> Append a THAPP record of command number `set` (an edge condition acts
   !> between two consecutive corners that got it from the same command).
   subroutine thermal_add_record(th, kind, id, p1, p2, set)
      type(thermal_t), intent(inout) :: th
      integer(ip), intent(in) :: kind, id, set
      real(wp), intent(in) :: p1, p2
      integer(ip) :: m
      if (.not. allocated(th%rec_kind)) then
         allocate (th%rec_kind(0), th%rec_id(0), th%rec_p1(0), th%rec_p2(0), th%rec_t0(0), &
                   th%rec_set(0))
      end if
      if (th%nrec >= size(th%rec_kind)) then
         m = max(16_ip, 2_ip*size(th%rec_kind))
         call grow_lists(th%nrec, m, th%rec_p1, th%rec_p2, th%rec_t0)
         call grow_lists(th%nrec, m, th%rec_kind, th%rec_id, th%rec_set)
      end if
      th%nrec = th%nrec + 1
      th%rec_kind(th%nrec) = kind; th%rec_id(th%nrec) = id; th%rec_set(th%nrec) = set
      th%rec_p1(th%nrec) = p1; th%rec_p2(th%nrec) = p2; th%rec_t0(th%nrec) = th%time
   end subroutine thermal_add_record

   !> Append one THIST sample (values of histories 1..nthis) at the current time.
   subroutine thermal_add_sample(th, values)
      type(thermal_t), intent(inout) :: th
      real(wp), intent(in) :: values(:)
      integer(ip) :: m, base
      if (.not. allocated(th%samp_time)) allocate (th%samp_time(0), th%samp_val(0))
      if (th%nsamp >= size(th%samp_time)) then
         m = max(64_ip, 2_ip*size(th%samp_time))
         call grow_array(th%samp_time, th%nsamp, m)
         call grow_array(th%samp_val, th%nsamp*max_thist, m*max_thist)
      end if
      th%nsamp = th%nsamp + 1
      th%samp_time(th%nsamp) = th%time
      base = (th%nsamp - 1)*max_thist
      th%samp_val(base + 1:base + max_thist) = 0.0_wp
      th%samp_val(base + 1:base + size(values)) = values
   end subroutine thermal_add_sample

end module model_thermal
