!> Material property values (manual Section 4.5, PROPERTY). UDEC keeps one
!> table indexed by material number: block properties (MAT n) and joint
!> properties (JMAT n) live side by side, and the manual's decks give joint
!> properties under `PROP MAT=n` as well. Values are a typed array indexed by
!> the ids that model_properties declares: `value(prop_jkn, mat)`.
module model_materials
   use core_kinds, only: wp
   use model_properties, only: nproperties
   implicit none
   private
   public :: material_table_t

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

   !> Store property `id` of material `mat` (ids: model_properties).
   subroutine material_set(this, mat, id, value)
      class(material_table_t), intent(inout) :: this
      integer, intent(in) :: mat, id
      real(wp), intent(in) :: value
      real(wp), allocatable :: v(:, :)
      logical, allocatable :: g(:, :)
      integer :: cap
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
      this%value(id, mat) = value
      this%given(id, mat) = .true.
      this%nmat = max(this%nmat, mat)
   end subroutine material_set

   !> Value of property `id` of material `mat` (0 when never given, as in UDEC).
   pure real(wp) function material_get(this, mat, id) result(value)
      class(material_table_t), intent(in) :: this
      integer, intent(in) :: mat, id
      value = 0.0_wp
      if (mat < 1 .or. mat > this%nmat) return
      value = this%value(id, mat)
   end function material_get

   pure logical function material_is_given(this, mat, id) result(given)
      class(material_table_t), intent(in) :: this
      integer, intent(in) :: mat, id
      given = .false.
      if (mat < 1 .or. mat > this%nmat) return
      given = this%given(id, mat)
   end function material_is_given

end module model_materials
