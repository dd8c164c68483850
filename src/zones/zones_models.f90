!> Constitutive models of zones (manual Section 3.2 Eq. 3 and CHANGE CONS):
!>   CONS 0  null: stresses are zero (excavated material)
!>   CONS 1  isotropic linear elasticity (K, G)
!>   CONS 3  elastic / perfectly plastic Mohr-Coulomb with tension cut-off
!>           (COH, FRIC = tan(phi), TENS, DIL = tan(psi)), non-associated
!>           flow when DIL differs from FRIC
!> One abstract type and a factory (`zone_model_create`): the engine calls
!> `update` once per group of zones sharing a model and a material, with
!> the loop over the zones inside the kernel.
!>
!> Stresses are tension positive; the plane-strain out-of-plane stress szz
!> takes part in the yield test. Strain increments are tensor components
!> (dexy = (du/dy + dv/dx)/2 * dt).
!>
!> Mohr-Coulomb (principal stresses s1 <= s2 <= s3, tension positive):
!>   shear   f_s = s1 - s3 N_phi + 2 c sqrt(N_phi) < 0,  N_phi = (1+sin phi)/(1-sin phi)
!>   tension f_t = sigma_t - s3 < 0, sigma_t = TENS, at most c / tan(phi)
!> The elastic trial stress is returned to the yield surface along the
!> plastic potential g = s1 - s3 N_psi (shear) or g = s3 (tension); near
!> the corner of the two surfaces the choice follows the bisector rule
!> h = s3 - sigma_t + a_p (s1 - s_p) (h > 0: tension) with
!> a_p = sqrt(1 + N_phi^2) + N_phi, s_p = sigma_t N_phi - 2 c sqrt(N_phi).
!> The principal directions do not change during the correction.
module zones_models
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use model_zones, only: zone_list_t, zone_elastic, zone_at_failure, zone_failed_past, zone_tension
   implicit none
   private
   public :: zone_props_t, zone_model_t, zone_model_create, known_cons

   integer, parameter :: known_cons(3) = [0, 1, 3]

   !> Properties of one zone group (material number).
   !> Tension limit standing for "none" (finite, so the corner test stays finite)
   real(wp), parameter :: tension_free = 1.0e30_wp

   type :: zone_props_t
      real(wp) :: bulk = 0.0_wp, shear = 0.0_wp, density = 0.0_wp
      real(wp) :: cohesion = 0.0_wp, friction = 0.0_wp, tension = 0.0_wp, dilation = 0.0_wp
      !> TENS given by PROPERTY; without it the only tension limit is the
      !> apex of the Mohr-Coulomb line, c / tan(phi) (none for phi = 0)
      logical :: tension_given = .false.
   end type zone_props_t

   type, abstract :: zone_model_t
   contains
      procedure(update_iface), deferred :: update
   end type zone_model_t

   abstract interface
      !> New stresses of zones idx(1:n) from their strain increments.
      subroutine update_iface(this, p, idx, n, dxx, dyy, dxy, zn)
         import :: zone_model_t, zone_props_t, zone_list_t, wp, ip
         class(zone_model_t), intent(in) :: this
         type(zone_props_t), intent(in) :: p
         integer(ip), intent(in) :: n
         integer(ip), intent(in) :: idx(n)
         real(wp), intent(in) :: dxx(n), dyy(n), dxy(n)
         type(zone_list_t), intent(inout) :: zn
      end subroutine update_iface
   end interface

   type, extends(zone_model_t) :: null_model_t
   contains
      procedure :: update => null_update
   end type null_model_t

   type, extends(zone_model_t) :: elastic_model_t
   contains
      procedure :: update => elastic_update
   end type elastic_model_t

   type, extends(zone_model_t) :: mohr_model_t
   contains
      procedure :: update => mohr_update
   end type mohr_model_t

contains

   !> The model of constitutive number `cons`; an unknown number is an error
   !> naming the known ones.
   subroutine zone_model_create(cons, model, error)
      integer, intent(in) :: cons
      class(zone_model_t), allocatable, intent(out) :: model
      type(error_t), allocatable, intent(out) :: error
      character(len=120) :: msg
      select case (cons)
      case (0)
         allocate (null_model_t :: model)
      case (1)
         allocate (elastic_model_t :: model)
      case (3)
         allocate (mohr_model_t :: model)
      case (4)
         call set_error(error, 'CYCLE: CONS 4 (Griffith fracture) applies to SDEF blocks only, '// &
                        'which are not available; zoned blocks know CONS 0, 1, 3')
      case default
         write (msg, '(a,i0,a)') 'CYCLE: unknown zone constitutive number CONS ', cons, '; known: 0, 1, 3'
         call set_error(error, trim(msg))
      end select
   end subroutine zone_model_create

   subroutine null_update(this, p, idx, n, dxx, dyy, dxy, zn)
      class(null_model_t), intent(in) :: this
      type(zone_props_t), intent(in) :: p
      integer(ip), intent(in) :: n
      integer(ip), intent(in) :: idx(n)
      real(wp), intent(in) :: dxx(n), dyy(n), dxy(n)
      type(zone_list_t), intent(inout) :: zn
      integer(ip) :: i, z
      do i = 1, n
         z = idx(i)
         zn%sxx(z) = 0.0_wp
         zn%syy(z) = 0.0_wp
         zn%sxy(z) = 0.0_wp
         zn%szz(z) = 0.0_wp
      end do
   end subroutine null_update

   !> Eq. 3: d sigma_ij = lambda d eps_v delta_ij + 2 mu d eps_ij (plane strain).
   subroutine elastic_update(this, p, idx, n, dxx, dyy, dxy, zn)
      class(elastic_model_t), intent(in) :: this
      type(zone_props_t), intent(in) :: p
      integer(ip), intent(in) :: n
      integer(ip), intent(in) :: idx(n)
      real(wp), intent(in) :: dxx(n), dyy(n), dxy(n)
      type(zone_list_t), intent(inout) :: zn
      integer(ip) :: i, z
      real(wp) :: lam, mu2, dv
      lam = p%bulk - 2.0_wp*p%shear/3.0_wp
      mu2 = 2.0_wp*p%shear
      do i = 1, n
         z = idx(i)
         dv = dxx(i) + dyy(i)
         zn%sxx(z) = zn%sxx(z) + lam*dv + mu2*dxx(i)
         zn%syy(z) = zn%syy(z) + lam*dv + mu2*dyy(i)
         zn%sxy(z) = zn%sxy(z) + mu2*dxy(i)
         zn%szz(z) = zn%szz(z) + lam*dv
      end do
   end subroutine elastic_update

   !> Elastic trial, then return to the Mohr-Coulomb surface (module header).
   subroutine mohr_update(this, p, idx, n, dxx, dyy, dxy, zn)
      class(mohr_model_t), intent(in) :: this
      type(zone_props_t), intent(in) :: p
      integer(ip), intent(in) :: n
      integer(ip), intent(in) :: idx(n)
      real(wp), intent(in) :: dxx(n), dyy(n), dxy(n)
      type(zone_list_t), intent(inout) :: zn
      integer(ip) :: i, z
      real(wp) :: lam, mu2, dv, a1, a2, sphi, spsi, nphi, npsi, rnphi, sigt, ap, sp
      real(wp) :: sxx, syy, sxy, szz, sm, rad, sa, sb, c2, s2, s(3), fs, ft, h, dl
      integer :: k1, k3, kz, j
      lam = p%bulk - 2.0_wp*p%shear/3.0_wp
      mu2 = 2.0_wp*p%shear
      a1 = p%bulk + 4.0_wp*p%shear/3.0_wp
      a2 = lam
      sphi = p%friction/sqrt(1.0_wp + p%friction**2)     ! sin(phi) from tan(phi)
      spsi = p%dilation/sqrt(1.0_wp + p%dilation**2)
      nphi = (1.0_wp + sphi)/(1.0_wp - sphi)
      npsi = (1.0_wp + spsi)/(1.0_wp - spsi)
      rnphi = sqrt(nphi)
      if (p%tension_given) then
         sigt = p%tension
         if (p%friction > 0.0_wp) sigt = min(sigt, p%cohesion/p%friction)
      else if (p%friction > 0.0_wp) then
         sigt = p%cohesion/p%friction
      else
         sigt = tension_free
      end if
      ap = sqrt(1.0_wp + nphi*nphi) + nphi
      sp = sigt*nphi - 2.0_wp*p%cohesion*rnphi
      do i = 1, n
         z = idx(i)
         dv = dxx(i) + dyy(i)
         sxx = zn%sxx(z) + lam*dv + mu2*dxx(i)
         syy = zn%syy(z) + lam*dv + mu2*dyy(i)
         sxy = zn%sxy(z) + mu2*dxy(i)
         szz = zn%szz(z) + lam*dv
         ! in-plane principal stresses sa <= sb and the direction of sa
         sm = 0.5_wp*(sxx + syy)
         rad = hypot(0.5_wp*(sxx - syy), sxy)
         sa = sm - rad
         sb = sm + rad
         if (rad > 0.0_wp) then
            c2 = 0.5_wp*(sxx - syy)/rad
            s2 = sxy/rad
         else
            c2 = 1.0_wp
            s2 = 0.0_wp
         end if
         ! order the three principal stresses: s(1) <= s(2) <= s(3)
         if (szz <= sa) then
            s = [szz, sa, sb]; kz = 1
         else if (szz <= sb) then
            s = [sa, szz, sb]; kz = 2
         else
            s = [sa, sb, szz]; kz = 3
         end if
         k1 = 1
         k3 = 3
         fs = s(k1) - s(k3)*nphi + 2.0_wp*p%cohesion*rnphi
         ft = sigt - s(k3)
         j = 0
         if (fs < 0.0_wp) then
            h = s(k3) - sigt + ap*(s(k1) - sp)
            if (ft < 0.0_wp .and. h > 0.0_wp) then
               j = 2
            else
               j = 1
            end if
         else if (ft < 0.0_wp) then
            j = 2
         end if
         if (j == 1) then
            ! shear: dsigma = -D deps_p, deps_p = dl (1, 0, -N_psi)
            dl = fs/((a1 - a2*npsi) - nphi*(a2 - a1*npsi))
            s(1) = s(1) - dl*(a1 - a2*npsi)
            s(2) = s(2) - dl*(a2 - a2*npsi)
            s(3) = s(3) - dl*(a2 - a1*npsi)
            zn%state(z) = zone_at_failure
         else if (j == 2) then
            dl = (s(3) - sigt)/a1
            s(1) = s(1) - dl*a2
            s(2) = s(2) - dl*a2
            s(3) = sigt
            zn%state(z) = zone_tension
         else if (zn%state(z) /= zone_elastic) then
            zn%state(z) = zone_failed_past
         end if
         if (j > 0) then
            select case (kz)
            case (1)
               szz = s(1); sa = s(2); sb = s(3)
            case (2)
               sa = s(1); szz = s(2); sb = s(3)
            case default
               sa = s(1); sb = s(2); szz = s(3)
            end select
            sm = 0.5_wp*(sa + sb)
            rad = 0.5_wp*(sb - sa)
            ! same principal directions as the trial: sxx - sm = rad c2
            sxx = sm + rad*c2
            syy = sm - rad*c2
            sxy = rad*s2
         end if
         zn%sxx(z) = sxx
         zn%syy(z) = syy
         zn%sxy(z) = sxy
         zn%szz(z) = szz
      end do
   end subroutine mohr_update

end module zones_models
