!> Material property table (manual Section 4.5, PROPERTY). UDEC keeps one table
!> indexed by material number: block properties (MAT n) and joint properties
!> (JMAT n) live side by side, and the manual's decks give joint properties
!> under `PROP MAT=n` as well. Values are stored by canonical property name.
module model_materials
   use core_kinds, only: wp
   implicit none
   private
   public :: material_table_t, property_names, nproperties, property_index, canonical_property

   !> Every property keyword of PROPERTY (aliases K/G map to BULK/SHEAR).
   integer, parameter :: name_len = 10
   integer, parameter :: nproperties = 45
   character(len=name_len), parameter :: property_names(nproperties) = [ &
      character(len=name_len) :: &
      'KN', 'KS', 'CCOHESION', 'CPERM', 'CDILATION', 'CFRICTION', 'CTENSILE', &
      'AZERO', 'ARES', 'JKN', 'JKS', 'JCOH', 'JDIL', 'JFRIC', 'JPERM', 'JTENSILE', &
      'JEN', 'JES', 'JIF', 'JR', 'BULK', 'SHEAR', 'DENSITY', 'COHESION', 'FRICTION', &
      'TENSILE', 'DILATION', 'TF', 'HBS', 'HBM', 'UCS', 'YCOMP', 'YIELD', 'RASTIFF', &
      'RSSTIFF', 'RLENGTH', 'RUAXIAL', 'RUSHEAR', 'RRFAC', 'RSEXP', 'RAEXP', &
      'SPECHEAT', 'THEXP', 'XCOND', 'YCOND']

   type :: material_table_t
      integer :: nmat = 0                       !< highest material number with data
      real(wp), allocatable :: value(:, :)      !< (nproperties, nmat)
      logical, allocatable :: given(:, :)       !< set by a PROPERTY command
   contains
      procedure :: set => material_set
      procedure :: get => material_get
      procedure :: is_given => material_is_given
   end type material_table_t

contains

   !> Canonical stored name of a PROPERTY keyword (K -> BULK, G -> SHEAR). COND is
   !> not stored: it sets XCOND and YCOND (manual Section 7.4.2), done by the caller.
   pure function canonical_property(keyword) result(name)
      character(len=*), intent(in) :: keyword
      character(len=name_len) :: name
      select case (keyword)
      case ('K'); name = 'BULK'
      case ('G'); name = 'SHEAR'
      case default; name = keyword(1:min(name_len, len(keyword)))
      end select
   end function canonical_property

   !> Index of a canonical property name, 0 if unknown.
   pure integer function property_index(name) result(k)
      character(len=*), intent(in) :: name
      do k = 1, nproperties
         if (property_names(k) == name) return
      end do
      k = 0
   end function property_index

   subroutine material_set(this, mat, name, value)
      class(material_table_t), intent(inout) :: this
      integer, intent(in) :: mat
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: value
      real(wp), allocatable :: v(:, :)
      logical, allocatable :: g(:, :)
      integer :: k, cap
      k = property_index(name)
      if (k == 0) return
      if (.not. allocated(this%value)) then
         allocate (this%value(nproperties, 0), this%given(nproperties, 0))
      end if
      if (mat > size(this%value, 2)) then
         cap = max(mat, 2*size(this%value, 2), 4)
         allocate (v(nproperties, cap), g(nproperties, cap))
         v = 0.0_wp
         g = .false.
         v(:, 1:size(this%value, 2)) = this%value
         g(:, 1:size(this%value, 2)) = this%given
         call move_alloc(v, this%value)
         call move_alloc(g, this%given)
      end if
      this%value(k, mat) = value
      this%given(k, mat) = .true.
      this%nmat = max(this%nmat, mat)
   end subroutine material_set

   !> Value of a property (0 when never given, as in UDEC).
   pure real(wp) function material_get(this, mat, name) result(value)
      class(material_table_t), intent(in) :: this
      integer, intent(in) :: mat
      character(len=*), intent(in) :: name
      integer :: k
      value = 0.0_wp
      k = property_index(name)
      if (k == 0 .or. mat < 1 .or. mat > this%nmat) return
      value = this%value(k, mat)
   end function material_get

   pure logical function material_is_given(this, mat, name) result(given)
      class(material_table_t), intent(in) :: this
      integer, intent(in) :: mat
      character(len=*), intent(in) :: name
      integer :: k
      given = .false.
      k = property_index(name)
      if (k == 0 .or. mat < 1 .or. mat > this%nmat) return
      given = this%given(k, mat)
   end function material_is_given

end module model_materials
