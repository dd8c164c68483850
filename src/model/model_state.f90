!> The whole problem state. Physics states arrive as allocatable components
!> with the issues that bring them (geometry, mechanics, zones, ...).
module model_state
   use core_kinds, only: wp
   use model_materials, only: material_table_t
   use model_geometry, only: geometry_t, geometry_init
   use model_mechanics, only: mechanics_t
   use model_history, only: history_t
   use model_boundary, only: boundary_t
   use model_be, only: be_t
   use model_structures, only: structure_t
   use model_reinforcement, only: reinforcement_t
   use model_fluid, only: fluid_t
   use model_tables, only: table_set_t
   use model_thermal, only: thermal_t
   use model_ffield, only: ffield_t
   implicit none
   private
   public :: model_t, model_reset

   type :: model_t
      character(len=:), allocatable :: heading   !< HEADING title ('' if none)
      type(material_table_t) :: materials         !< PROPERTY table
      real(wp) :: gravity(2) = 0.0_wp             !< GRAVITY gx gy
      type(geometry_t) :: geometry                !< blocks, corners, contacts, domains
      logical :: cycled = .false.                 !< a CYCLE or GENERATE has run
      type(mechanics_t) :: mech                   !< clock, damping, time step settings
      type(history_t) :: hist                     !< HISTORY variables and samples
      type(boundary_t) :: bound                   !< BOUNDARY conditions (model_boundary)
      type(be_t) :: be                            !< BE far field (model_be)
      !> STRUCTURE liners (model_structures); not allocated: no structure code runs
      type(structure_t), allocatable :: structures
      !> REINFORCE and CABLE (model_reinforcement); not allocated: no reinforcement code runs
      type(reinforcement_t), allocatable :: reinforcement
      !> joint fluid flow (model_fluid): allocated by the first fluid command;
      !> not allocated, no fluid code runs
      type(fluid_t), allocatable :: fluid
      !> heat conduction (model_thermal): allocated by THERMAL or the first thermal
      !> command; not allocated, no thermal code runs
      type(thermal_t), allocatable :: thermal
      type(ffield_t) :: ffield                    !< FFIELD free-field column (model_ffield)
      type(table_set_t) :: tables                 !< TABLE n x y ... (model_tables)
   end type model_t

contains

   !> A fresh model (START / NEW).
   subroutine model_reset(model)
      type(model_t), intent(out) :: model
      model%heading = ''
      call geometry_init(model%geometry)
   end subroutine model_reset

end module model_state
