!> Time histories (manual Section 4.5 HISTORY): which variables are sampled,
!> where, and the samples taken so far. Sampling itself is done by the engine
!> (engine_history); plotting and writing read the arrays here.
module model_history
   use core_kinds, only: wp, ip
   use core_arrays, only: grow_array, grow_lists
   implicit none
   private
   public :: history_t, history_add, history_record, history_clear, history_first
   public :: hist_xvel, hist_yvel, hist_xdis, hist_ydis, hist_bfx, hist_bfy, hist_bfm
   public :: hist_ndis, hist_sdis, hist_nstr, hist_sstr, hist_unbal, hist_damp
   public :: hist_sxx, hist_sxy, hist_syy, hist_none, hist_names
   public :: hist_gxvel, hist_gyvel, hist_gxdis, hist_gydis, hist_gridpoint_kind
   public :: hist_xhis, hist_yhis, hist_keyword, hist_unit, hist_address
   public :: hist_caxial, hist_raxial, hist_rshear, hist_srat

   integer, parameter :: hist_xvel = 1, hist_yvel = 2, hist_xdis = 3, hist_ydis = 4
   integer, parameter :: hist_bfx = 5, hist_bfy = 6, hist_bfm = 7
   integer, parameter :: hist_ndis = 8, hist_sdis = 9, hist_nstr = 10, hist_sstr = 11
   integer, parameter :: hist_unbal = 12, hist_damp = 13
   integer, parameter :: hist_sxx = 14, hist_sxy = 15, hist_syy = 16
   integer, parameter :: hist_none = 17      !< a variable of physics not yet available (reads 0)
   !> XVEL YVEL XDIS YDIS taken at a gridpoint of a deformable block (entity:
   !> gridpoint id) rather than at a rigid-block corner (entity: corner id).
   !> The stress kinds SXX SXY SYY have a zone id as entity.
   integer, parameter :: hist_gxvel = 18, hist_gyvel = 19, hist_gxdis = 20, hist_gydis = 21
   !> XHIS, YHIS: value of the x / y boundary history in the step (FXHIS, FYHIS)
   integer, parameter :: hist_xhis = 22, hist_yhis = 23
   !> ADDRESS i j (manual Section 6.1 offsets): entity id in `entity`, the
   !> entity kind (model_address ak_*) in x and the offset j in y
   integer, parameter :: hist_address = 24
   !> CAXIAL n: axial force of cable element n; RAXIAL n, RSHEAR n: axial and
   !> shear spring force of local reinforcement element n (Section 3.10)
   integer, parameter :: hist_caxial = 25, hist_raxial = 26, hist_rshear = 27
   !> SRAT n: shear stress ratio of contact n, |shear| / shear strength
   !> (contact_joint_law joint_shear_ratio; Appendix B, Application D)
   integer, parameter :: hist_srat = 28
   !> Names used in headers and listings, indexed by the kinds above (the
   !> list only grows at the end: save files record it).
   character(len=5), parameter :: hist_names(28) = [character(len=5) :: &
      'XVEL', 'YVEL', 'XDIS', 'YDIS', 'BFX', 'BFY', 'BFM', 'NDIS', 'SDIS', 'NSTR', &
      'SSTR', 'UNBAL', 'DAMP', 'SXX', 'SXY', 'SYY', 'N/A', 'GXVEL', 'GYVEL', 'GXDIS', 'GYDIS', &
      'XHIS', 'YHIS', 'ADDR', 'CAXIA', 'RAXIA', 'RSHEA', 'SRAT']

   type :: history_t
      integer :: n = 0                          !< number of variables
      integer, allocatable :: kind(:)           !< hist_* per variable
      integer(ip), allocatable :: entity(:)     !< corner / block / contact id (0: none)
      real(wp), allocatable :: x(:), y(:)       !< point asked for (XVEL etc.)
      real(wp), allocatable :: px(:), py(:)     !< point chosen (nearest corner)
      integer(ip) :: ncyc = 10                  !< sample every ncyc cycles
      integer :: typed = 0                      !< TYPE n: shown while cycling (0: none)
      integer(ip) :: nsample = 0
      real(wp), allocatable :: time(:)          !< time of each sample
      integer(ip), allocatable :: step(:)       !< cycle of each sample
      real(wp), allocatable :: values(:, :)     !< (variable, sample)
      !> first sample a variable has (a HISTORY given after samples were taken
      !> starts later; the values before it are not samples); 0 or 1: all
      integer(ip), allocatable :: first_sample(:)
   end type history_t

contains

   !> The manual's HISTORY keyword of a kind, for headers and listings: the
   !> gridpoint kinds read as the point kinds they were given as (XDIS, not the
   !> internal GXDIS; manual Section 4.5 HISTORY). hist_names stays the stored list.
   pure function hist_keyword(kind) result(name)
      integer, intent(in) :: kind
      character(len=5) :: name
      name = hist_names(hist_gridpoint_kind(kind, .false.))
   end function hist_keyword

   !> The SI unit of a history kind's values (UDEC's commands take any
   !> consistent units; the manual's decks and ours use SI), for plot axes
   !> and legends; blank for a ratio or a multiplier.
   pure function hist_unit(kind) result(unit)
      integer, intent(in) :: kind
      character(len=5) :: unit
      select case (hist_gridpoint_kind(kind, .false.))
      case (hist_xvel, hist_yvel)
         unit = 'm/s'
      case (hist_xdis, hist_ydis, hist_ndis, hist_sdis)
         unit = 'm'
      case (hist_bfx, hist_bfy, hist_unbal, hist_caxial, hist_raxial, hist_rshear)
         unit = 'N'
      case (hist_bfm)
         unit = 'N m'
      case (hist_nstr, hist_sstr, hist_sxx, hist_sxy, hist_syy)
         unit = 'Pa'
      case default
         unit = ''
      end select
   end function hist_unit

   !> The gridpoint kind of a point kind (hist_xvel -> hist_gxvel, ...) and
   !> back: `to_gridpoint` chooses the direction; other kinds are returned as given.
   pure integer function hist_gridpoint_kind(kind, to_gridpoint) result(k)
      integer, intent(in) :: kind
      logical, intent(in) :: to_gridpoint
      k = kind
      if (to_gridpoint) then
         if (kind >= hist_xvel .and. kind <= hist_ydis) k = kind - hist_xvel + hist_gxvel
      else
         if (kind >= hist_gxvel .and. kind <= hist_gydis) k = kind - hist_gxvel + hist_xvel
      end if
   end function hist_gridpoint_kind

   !> Append a variable definition; samples taken so far are kept for the
   !> existing variables (the new one reads zero before it was defined).
   subroutine history_add(h, kind, entity, x, y, px, py)
      type(history_t), intent(inout) :: h
      integer, intent(in) :: kind
      integer(ip), intent(in) :: entity
      real(wp), intent(in) :: x, y, px, py
      integer(ip), allocatable :: ie(:)
      real(wp), allocatable :: v(:, :)
      integer :: n
      n = h%n
      call grow_lists(n, n + 1, h%x, h%y, h%px, h%py)
      call grow_lists(n, n + 1, h%kind, h%entity)
      h%kind(n + 1) = kind
      h%entity(n + 1) = entity
      h%x(n + 1) = x
      h%y(n + 1) = y
      h%px(n + 1) = px
      h%py(n + 1) = py
      allocate (ie(n + 1)); ie = 1
      if (n > 0 .and. allocated(h%first_sample)) ie(1:n) = h%first_sample(1:n)
      ie(n + 1) = h%nsample + 1
      call move_alloc(ie, h%first_sample)
      if (allocated(h%values)) then
         allocate (v(n + 1, size(h%values, 2)))
         v = 0.0_wp
         if (n > 0) v(1:n, :) = h%values(1:n, :)
         call move_alloc(v, h%values)
      end if
      h%n = n + 1
   end subroutine history_add

   !> Store one sample (all variables) at time `t`, cycle `step`.
   subroutine history_record(h, t, step, vals)
      type(history_t), intent(inout) :: h
      real(wp), intent(in) :: t
      integer(ip), intent(in) :: step
      real(wp), intent(in) :: vals(:)
      real(wp), allocatable :: v(:, :)
      integer(ip) :: m
      if (h%n == 0) return
      if (.not. allocated(h%time)) then
         allocate (h%time(256), h%step(256), h%values(h%n, 256))
      else if (h%nsample >= size(h%time)) then
         m = 2*size(h%time)
         call grow_array(h%time, h%nsample, m)
         call grow_array(h%step, h%nsample, m)
         allocate (v(h%n, m)); v(:, 1:h%nsample) = h%values(:, 1:h%nsample)
         call move_alloc(v, h%values)
      end if
      h%nsample = h%nsample + 1
      h%time(h%nsample) = t
      h%step(h%nsample) = step
      h%values(:, h%nsample) = vals(1:h%n)
   end subroutine history_record

   !> RESET HIST (manual 4.5: the current selection of histories is reset, "followed by a
   !> new HISTORY command"): the variables and their samples are forgotten, so the next
   !> HISTORY line numbers its variables from 1 again (Application A's deck numbers the
   !> histories given after its RESET HIST 1-16). The sampling interval NCYC and the
   !> TYPE setting stay.
   subroutine history_clear(h)
      type(history_t), intent(inout) :: h
      h = history_t(ncyc=h%ncyc, typed=h%typed)
   end subroutine history_clear

   !> The first sample of variable `i` (1 when it was defined before any
   !> sample; nsample + 1 when it has none yet).
   pure integer(ip) function history_first(h, i) result(s)
      type(history_t), intent(in) :: h
      integer, intent(in) :: i
      s = 1
      if (.not. allocated(h%first_sample)) return
      if (i < 1 .or. i > size(h%first_sample)) return
      s = max(1_ip, h%first_sample(i))
   end function history_first

end module model_history
