!> Boundary-element far field (manual Section 4.5 BE, Section 3 "Boundary
!> Element Representation of the Far Field"): the settings given by BE MAT,
!> GEN, FIX, HALF and, after BE STIFFNESS, the link: the corners the far
!> field acts on, its elements, the corner positions when it was linked and
!> the elastic constants it was built with. The stiffness matrix itself is
!> work (`kmat`), rebuilt from these after a RESTART (src/be/be_far_field).
module model_be
   use core_kinds, only: wp, ip
   implicit none
   private
   public :: be_t, be_clear_link

   type :: be_t
      integer :: mat = 0                        !< BE MAT n (0: not given)
      logical :: half = .false.                 !< BE HALF given
      logical :: fix = .false.                  !< BE FIX given
      real(wp) :: xh = 0.0_wp, yh = 0.0_wp      !< point fixed in x
      real(wp) :: xv = 0.0_wp, yv = 0.0_wp      !< point fixed in y
      integer(ip) :: nc = 0                     !< corners (nodes) of the elements
      integer(ip) :: ne = 0                     !< elements (free block edges)
      integer(ip), allocatable :: corner(:)     !< node i: corner id
      integer(ip), allocatable :: ea(:), eb(:)  !< element e: nodes, clockwise
      logical :: linked = .false.               !< BE STIFFNESS done
      real(wp) :: g = 0.0_wp, nu = 0.0_wp       !< far-field constants at the link
      real(wp), allocatable :: x0(:), y0(:)     !< node positions at the link
      ! work (not saved)
      real(wp), allocatable :: kmat(:, :)       !< 2 nc x 2 nc, F = -kmat (u - u0)
      real(wp), allocatable :: u(:), f(:)       !< displacement since the link, force
   end type be_t

contains

   !> Forget the link (a new BE GEN): elements and work go, settings stay.
   subroutine be_clear_link(be)
      type(be_t), intent(inout) :: be
      be%linked = .false.
      be%nc = 0
      be%ne = 0
      if (allocated(be%corner)) deallocate (be%corner)
      if (allocated(be%ea)) deallocate (be%ea)
      if (allocated(be%eb)) deallocate (be%eb)
      if (allocated(be%x0)) deallocate (be%x0)
      if (allocated(be%y0)) deallocate (be%y0)
      if (allocated(be%kmat)) deallocate (be%kmat)
      if (allocated(be%u)) deallocate (be%u)
      if (allocated(be%f)) deallocate (be%f)
   end subroutine be_clear_link

end module model_be
