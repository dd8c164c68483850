!> Plot devices: a device writes a finished scene to a file. Each device
!> extends `plot_device_t`; `plot_factory` creates them by name.
module plot_device
   use core_error, only: error_t
   use plot_scene, only: plot_scene_t
   implicit none
   private
   public :: plot_device_t

   type, abstract :: plot_device_t
      !> The device's name as SET PLOT spells it ("PS", "PNG"), given by
      !> plot_factory when it creates the device.
      character(len=8) :: label = ''
   contains
      procedure(device_write), deferred :: write
      procedure, non_overridable :: name => device_name
   end type plot_device_t

   abstract interface
      !> Write `scene` to the file `path` (replaced if it exists).
      subroutine device_write(this, scene, path, error)
         import :: plot_device_t, plot_scene_t, error_t
         class(plot_device_t), intent(in) :: this
         type(plot_scene_t), intent(in) :: scene
         character(len=*), intent(in) :: path
         type(error_t), allocatable, intent(out) :: error
      end subroutine device_write
   end interface

contains

   !> The device's name as SET PLOT spells it ("PS", "PNG").
   function device_name(this) result(name)
      class(plot_device_t), intent(in) :: this
      character(len=:), allocatable :: name
      name = trim(this%label)
   end function device_name

end module plot_device
