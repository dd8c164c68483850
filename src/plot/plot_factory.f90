!> The plot devices by name, and the choice of device for a file name:
!> `.ps` / `.eps` PostScript, `.png` PNG, any other name the route's device.
module plot_factory
   use core_error, only: error_t, set_error
   use core_strings, only: to_upper
   use plot_device, only: plot_device_t
   use plot_ps, only: ps_device_t
   use plot_png, only: png_device_t
   implicit none
   private
   public :: plot_device_names, plot_device_create, plot_device_for_file

   !> Every device the factory builds (SET PLOT names).
   character(len=4), parameter :: plot_device_names(2) = [character(len=4) :: 'PS', 'PNG']

contains

   !> Create the device called `name` (upper case).
   subroutine plot_device_create(name, device, error)
      character(len=*), intent(in) :: name
      class(plot_device_t), allocatable, intent(out) :: device
      type(error_t), allocatable, intent(out) :: error
      select case (name)
      case ('PS')
         allocate (device, source=ps_device_t(label='PS'))
      case ('PNG')
         allocate (device, source=png_device_t(label='PNG'))
      case default
         call set_error(error, "unknown plot device '"//name//"' (known devices: PS, PNG)")
      end select
   end subroutine plot_device_create

   !> Name of the device that writes `file`: by extension, else `route`.
   function plot_device_for_file(file, route) result(name)
      character(len=*), intent(in) :: file, route
      character(len=:), allocatable :: name
      character(len=:), allocatable :: ext
      integer :: dot, slash
      dot = index(file, '.', back=.true.)
      slash = max(index(file, '/', back=.true.), index(file, '\', back=.true.))
      ext = ''
      if (dot > slash .and. dot > 0) ext = to_upper(file(dot + 1:))
      select case (ext)
      case ('PS', 'EPS')
         name = 'PS'
      case ('PNG')
         name = 'PNG'
      case default
         name = route
      end select
   end function plot_device_for_file

end module plot_factory
