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
!> Past an edge of the surface (large increments) the return uses the
!> edges and corners as well (mohr_return), so every zone ends on or inside
!> its surface. The principal directions do not change during the
!> correction.
module zones_models
   use core_kinds, only: wp, ip, l1
   use core_error, only: error_t, set_error
   use model_zones, only: zone_list_t, zone_elastic, zone_at_failure, zone_failed_past, zone_tension
   use model_materials, only: material_table_t
   use model_properties, only: prop_bulk, prop_cohesion, prop_density, prop_dilation, &
                               prop_friction, prop_shear, prop_tensile
   implicit none
   private
   public :: zone_props_t, zone_model_t, zone_model_create, known_cons, zone_props_of
   public :: zone_groups, elastic_model_t, elastic_constants, elastic_zone

   integer, parameter :: known_cons(3) = [0, 1, 3]

   !> Properties of one zone group (material number).
   !> Tension limit standing for "none" (finite, so the corner test stays finite)
   real(wp), parameter :: tension_free = 1.0e30_wp

   !> Active sets tried by mohr_return (planes 1-6 of its header): the
   !> single planes, the pairs, the triples (0: unused slot)
   integer, parameter :: plane_sets(3, 41) = reshape([ &
                  1, 0, 0, 2, 0, 0, 3, 0, 0, 4, 0, 0, 5, 0, 0, 6, 0, 0, 1, 2, 0, 1, 3, 0, 1, 4, 0, &
                  1, 5, 0, 1, 6, 0, 2, 3, 0, 2, 4, 0, 2, 5, 0, 2, 6, 0, 3, 4, 0, 3, 5, 0, 3, 6, 0, &
                  4, 5, 0, 4, 6, 0, 5, 6, 0, 1, 2, 3, 1, 2, 4, 1, 2, 5, 1, 2, 6, 1, 3, 4, 1, 3, 5, &
                  1, 3, 6, 1, 4, 5, 1, 4, 6, 1, 5, 6, 2, 3, 4, 2, 3, 5, 2, 3, 6, 2, 4, 5, 2, 4, 6, &
                  2, 5, 6, 3, 4, 5, 3, 4, 6, 3, 5, 6, 4, 5, 6], [3, 41])

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
      !> return stresses changed outside the model onto its surface
      procedure :: admissible => no_admissible
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
      procedure :: admissible => mohr_admissible
   end type mohr_model_t

   !> Constants of the Mohr-Coulomb return for one property set.
   type :: mohr_constants_t
      real(wp) :: a1 = 0.0_wp, a2 = 0.0_wp, mu2 = 0.0_wp   !< K + 4G/3, K - 2G/3, 2G
      real(wp) :: nphi = 1.0_wp, npsi = 1.0_wp, k = 0.0_wp  !< N_phi, N_psi, 2 c sqrt(N_phi)
      real(wp) :: sigt = 0.0_wp, ap = 0.0_wp, sp = 0.0_wp  !< tension limit, bisector constants
      !> shear return on the face: D m (compressive, intermediate, tensile
      !> component) and n . D m
      real(wp) :: dm_lo = 0.0_wp, dm_mi = 0.0_wp, dm_hi = 0.0_wp, shear_den = 1.0_wp
   end type mohr_constants_t

contains

   !> Zones 1..n grouped by (cons, material), groups in the order of their
   !> first zone: group g holds zones gidx(gstart(g):gstart(g+1)-1), in zone
   !> order; zgroup(z) is the group of zone z, 0 for a zone not `used`. The
   !> set-up of the zone cycle and of the free-field column share it.
   subroutine zone_groups(cons, mat, used, zgroup, gcons, gmat, gstart, gidx)
      integer(ip), intent(in) :: cons(:), mat(:)
      logical(l1), intent(in) :: used(:)
      integer, allocatable, intent(out) :: zgroup(:), gcons(:), gmat(:), gstart(:)
      integer(ip), allocatable, intent(out) :: gidx(:)
      integer(ip) :: z
      integer :: g, ng
      integer, allocatable :: gcount(:), fill(:)
      allocate (zgroup(max(1, size(cons))), gcount(0), gcons(0), gmat(0))
      zgroup = 0
      ng = 0
      do z = 1, size(cons)
         if (.not. used(z)) cycle
         do g = 1, ng
            if (gcons(g) == cons(z) .and. gmat(g) == mat(z)) exit
         end do
         if (g > ng) then
            ng = ng + 1
            gcons = [gcons, cons(z)]
            gmat = [gmat, mat(z)]
            gcount = [gcount, 0]
            g = ng
         end if
         zgroup(z) = g
         gcount(g) = gcount(g) + 1
      end do
      allocate (gstart(ng + 1), gidx(max(1, sum(gcount))))
      gstart(1) = 1
      do g = 1, ng
         gstart(g + 1) = gstart(g) + gcount(g)
      end do
      fill = gstart(1:ng)
      do z = 1, size(cons)
         g = zgroup(z)
         if (g == 0) cycle
         gidx(fill(g)) = z
         fill(g) = fill(g) + 1
      end do
   end subroutine zone_groups

   !> The zone properties of material `mat` (PROPERTY's typed table).
   type(zone_props_t) function zone_props_of(mats, mat) result(props)
      type(material_table_t), intent(in) :: mats
      integer, intent(in) :: mat
      props%bulk = mats%get(mat, prop_bulk)
      props%shear = mats%get(mat, prop_shear)
      props%density = mats%get(mat, prop_density)
      props%cohesion = mats%get(mat, prop_cohesion)
      props%friction = mats%get(mat, prop_friction)
      props%tension = mats%get(mat, prop_tensile)
      props%tension_given = mats%is_given(mat, prop_tensile)
      props%dilation = mats%get(mat, prop_dilation)
   end function zone_props_of

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
      real(wp) :: lam, mu2
      call elastic_constants(p, lam, mu2)
      do i = 1, n
         z = idx(i)
         call elastic_zone(lam, mu2, dxx(i), dyy(i), dxy(i), zn%sxx(z), zn%syy(z), zn%sxy(z), zn%szz(z))
      end do
   end subroutine elastic_update

   !> Lame's lambda and 2 mu of the elastic law (elastic_update).
   pure subroutine elastic_constants(p, lam, mu2)
      type(zone_props_t), intent(in) :: p
      real(wp), intent(out) :: lam, mu2
      lam = p%bulk - 2.0_wp*p%shear/3.0_wp
      mu2 = 2.0_wp*p%shear
   end subroutine elastic_constants

   !> Eq. 3 for one zone: the stresses plus the increment of the strain
   !> increments dxx, dyy, dxy (elastic_update; the fused zone pass of
   !> zones_mechanics calls it inside its own loop).
   pure subroutine elastic_zone(lam, mu2, dxx, dyy, dxy, sxx, syy, sxy, szz)
      real(wp), intent(in) :: lam, mu2, dxx, dyy, dxy
      real(wp), intent(inout) :: sxx, syy, sxy, szz
      real(wp) :: dv
      dv = dxx + dyy
      sxx = sxx + lam*dv + mu2*dxx
      syy = syy + lam*dv + mu2*dyy
      sxy = sxy + mu2*dxy
      szz = szz + lam*dv
   end subroutine elastic_zone

   !> Elastic trial, then return to the Mohr-Coulomb surface (module header).
   subroutine mohr_update(this, p, idx, n, dxx, dyy, dxy, zn)
      class(mohr_model_t), intent(in) :: this
      type(zone_props_t), intent(in) :: p
      integer(ip), intent(in) :: n
      integer(ip), intent(in) :: idx(n)
      real(wp), intent(in) :: dxx(n), dyy(n), dxy(n)
      type(zone_list_t), intent(inout) :: zn
      type(mohr_constants_t) :: mc
      integer(ip) :: i, z
      integer :: mode
      real(wp) :: dv
      call mohr_constants(p, mc)
      do i = 1, n
         z = idx(i)
         dv = dxx(i) + dyy(i)
         zn%sxx(z) = zn%sxx(z) + mc%a2*dv + mc%mu2*dxx(i)
         zn%syy(z) = zn%syy(z) + mc%a2*dv + mc%mu2*dyy(i)
         zn%sxy(z) = zn%sxy(z) + mc%mu2*dxy(i)
         zn%szz(z) = zn%szz(z) + mc%a2*dv
         call mohr_zone_return(mc, zn%sxx(z), zn%syy(z), zn%sxy(z), zn%szz(z), mode)
         if (mode == 1) then
            zn%state(z) = zone_at_failure
         else if (mode == 2) then
            zn%state(z) = zone_tension
         else if (zn%state(z) /= zone_elastic) then
            zn%state(z) = zone_failed_past
         end if
      end do
   end subroutine mohr_update

   !> Stresses changed after the model call (the mixed discretization's
   !> pairing of the in-plane mean stress) are brought back onto the
   !> surface keeping that mean, which the pairing has just set: along
   !> the straight line towards (sm, sm, sm), sm = (sxx + syy)/2, the
   !> in-plane deviator shrinks and szz moves towards sm. The criterion is
   !> the largest of nine planes in principal stresses, N_phi s_j - s_i -
   !> K (i /= j) and s_i - sigma_t, each linear along the line, so the
   !> point where the last of them is met is exact. Where (sm, sm, sm) is
   !> not inside (in-plane mean beyond the tension limit) the ordinary
   !> return is used. Zones inside keep their stress and state; nback
   !> counts the zones brought back.
   subroutine mohr_admissible(this, p, idx, n, zn, nback)
      class(mohr_model_t), intent(in) :: this
      type(zone_props_t), intent(in) :: p
      integer(ip), intent(in) :: n
      integer(ip), intent(in) :: idx(n)
      type(zone_list_t), intent(inout) :: zn
      integer(ip), intent(inout) :: nback
      type(mohr_constants_t) :: mc
      integer(ip) :: i, z
      integer :: mode, a, b
      real(wp) :: sm, rad, s(3), tol, t, v0, v1, u
      call mohr_constants(p, mc)
      do i = 1, n
         z = idx(i)
         sm = 0.5_wp*(zn%sxx(z) + zn%syy(z))
         rad = sqrt(0.25_wp*(zn%sxx(z) - zn%syy(z))**2 + zn%sxy(z)**2)
         s = [sm - rad, sm + rad, zn%szz(z)]
         tol = 1.0e-12_wp*(max(abs(s(1)), abs(s(2)), abs(s(3))) + mc%k)
         if (max(mc%nphi*max(s(2), s(3)) - min(s(1), s(3)) - mc%k, max(s(2), s(3)) - mc%sigt) <= tol) cycle
         nback = nback + 1
         if (mohr_yield(mc, [sm, sm, sm]) < -tol) then
            ! s + t ((sm, sm, sm) - s): each plane from v0 (t = 0) to v1 (t = 1 < 0)
            t = 0.0_wp
            do a = 1, 3
               v0 = s(a) - mc%sigt
               v1 = sm - mc%sigt
               if (v0 > 0.0_wp) t = max(t, v0/(v0 - v1))
               do b = 1, 3
                  if (b == a) cycle
                  v0 = mc%nphi*s(b) - s(a) - mc%k
                  v1 = (mc%nphi - 1.0_wp)*sm - mc%k
                  if (v0 > 0.0_wp) t = max(t, v0/(v0 - v1))
               end do
            end do
            u = 1.0_wp - t
            zn%sxx(z) = sm + u*(zn%sxx(z) - sm)
            zn%syy(z) = sm + u*(zn%syy(z) - sm)
            zn%sxy(z) = u*zn%sxy(z)
            zn%szz(z) = sm + u*(zn%szz(z) - sm)
            mode = 1
            if (maxval([sm + u*rad, zn%szz(z)]) >= mc%sigt - tol) mode = 2
         else
            call mohr_zone_return(mc, zn%sxx(z), zn%syy(z), zn%sxy(z), zn%szz(z), mode)
         end if
         if (mode == 1) then
            zn%state(z) = zone_at_failure
         else
            zn%state(z) = zone_tension
         end if
      end do
   end subroutine mohr_admissible

   !> No yield surface: any stress is admissible.
   subroutine no_admissible(this, p, idx, n, zn, nback)
      class(zone_model_t), intent(in) :: this
      type(zone_props_t), intent(in) :: p
      integer(ip), intent(in) :: n
      integer(ip), intent(in) :: idx(n)
      type(zone_list_t), intent(inout) :: zn
      integer(ip), intent(inout) :: nback
   end subroutine no_admissible

   !> Constants of one Mohr-Coulomb group.
   pure subroutine mohr_constants(p, mc)
      type(zone_props_t), intent(in) :: p
      type(mohr_constants_t), intent(out) :: mc
      real(wp) :: sphi, spsi
      mc%a2 = p%bulk - 2.0_wp*p%shear/3.0_wp
      mc%mu2 = 2.0_wp*p%shear
      mc%a1 = mc%a2 + mc%mu2
      sphi = p%friction/sqrt(1.0_wp + p%friction**2)     ! sin(phi) from tan(phi)
      spsi = p%dilation/sqrt(1.0_wp + p%dilation**2)
      mc%nphi = (1.0_wp + sphi)/(1.0_wp - sphi)
      mc%npsi = (1.0_wp + spsi)/(1.0_wp - spsi)
      mc%k = 2.0_wp*p%cohesion*sqrt(mc%nphi)
      if (p%tension_given) then
         mc%sigt = p%tension
         if (p%friction > 0.0_wp) mc%sigt = min(mc%sigt, p%cohesion/p%friction)
      else if (p%friction > 0.0_wp) then
         mc%sigt = p%cohesion/p%friction
      else
         mc%sigt = tension_free
      end if
      mc%ap = sqrt(1.0_wp + mc%nphi*mc%nphi) + mc%nphi
      mc%sp = mc%sigt*mc%nphi - mc%k
      mc%dm_lo = mc%a2*mc%npsi - mc%a1
      mc%dm_mi = mc%a2*(mc%npsi - 1.0_wp)
      mc%dm_hi = mc%a1*mc%npsi - mc%a2
      mc%shear_den = mc%nphi*mc%dm_hi - mc%dm_lo
   end subroutine mohr_constants

   !> Return of one zone's stress (in place): principal stresses in the
   !> plane and szz, mohr_return, back along the same principal directions.
   !> mode: 0 elastic, 1 shear yield, 2 tension yield.
   subroutine mohr_zone_return(mc, sxx, syy, sxy, szz, mode)
      type(mohr_constants_t), intent(in) :: mc
      real(wp), intent(inout) :: sxx, syy, sxy, szz
      integer, intent(out) :: mode
      real(wp) :: sm, rad, c2, s2, s(3), smax, smin
      sm = 0.5_wp*(sxx + syy)
      rad = sqrt(0.25_wp*(sxx - syy)**2 + sxy*sxy)      ! (hypot: a libm call, a quarter of the step)
      ! inside (mohr_yield, as mohr_return tests it): nothing to do
      smax = max(sm + rad, szz)
      smin = min(sm - rad, szz)
      mode = 0
      if (max(mc%nphi*smax - smin - mc%k, smax - mc%sigt) <= &
          1.0e-12_wp*(max(abs(smax), abs(smin)) + mc%k)) return
      if (rad > 0.0_wp) then
         c2 = 0.5_wp*(sxx - syy)/rad
         s2 = sxy/rad
      else
         c2 = 1.0_wp
         s2 = 0.0_wp
      end if
      ! s(1) along the direction of the smaller in-plane principal stress,
      ! s(2) along the larger one, s(3) = szz
      s = [sm - rad, sm + rad, szz]
      call mohr_return(mc, s, mode)
      if (mode == 0) return
      ! same principal directions as the trial: sxx - sm = (s(2) - s(1))/2 c2
      sm = 0.5_wp*(s(1) + s(2))
      rad = 0.5_wp*(s(2) - s(1))
      sxx = sm + rad*c2
      syy = sm - rad*c2
      sxy = rad*s2
      szz = s(3)
   end subroutine mohr_zone_return

   !> Yield function of the full Mohr-Coulomb criterion with tension
   !> cut-off on principal stresses in any order (> 0: outside).
   pure real(wp) function mohr_yield(mc, s) result(f)
      type(mohr_constants_t), intent(in) :: mc
      real(wp), intent(in) :: s(3)
      real(wp) :: smax
      smax = max(s(1), s(2), s(3))
      f = max(smax*mc%nphi - min(s(1), s(2), s(3)) - mc%k, smax - mc%sigt)
   end function mohr_yield

   !> Return of the principal stresses s (any order; directions fixed) to
   !> the Mohr-Coulomb surface with tension cut-off. With the trial ordered
   !> s_l <= s_m <= s_h the surface near it is made of six planes: shear
   !> N_phi s_h - s_l = K (the face), N_phi s_m - s_l = K and N_phi s_h -
   !> s_m = K (the edges where the order of two stresses changes), and the
   !> tension planes s_h, s_m, s_l = sigma_t. The stress is
   !>   s = s_trial - D sum_k lambda_k m_k,  lambda_k >= 0,
   !> with f_k(s) = 0 on the active planes (flow m = N_psi e_tens - e_comp
   !> on a shear plane, e_i on a tension plane) and every plane satisfied.
   !> The active set is the first consistent one of: the plane the
   !> single-surface rule picks (shear, or tension by the bisector h of the
   !> module header), the other single planes, pairs, triples. A single
   !> plane is the usual return; the edges and corners take over when a
   !> large increment carries the trial past them (the single-plane return
   !> would then leave the stress outside another plane). Should no set be
   !> consistent, the stress goes onto the surface along the straight line
   !> from the trial to a point of the hydrostatic axis inside the surface.
   subroutine mohr_return(mc, s, mode)
      type(mohr_constants_t), intent(in) :: mc
      real(wp), intent(inout) :: s(3)
      integer, intent(out) :: mode
      integer, parameter :: nplane = 6
      real(wp) :: pn(3, nplane), pm(3, nplane), pb(nplane), dm(3, nplane)
      real(wp) :: st(3), trial(nplane), tol, h, x0, cap, f0, f1, t, hi_t, sn(3)
      integer :: ord(3), lo, mi, hi, k, first, iset, m, members(3)
      logical :: ok
      mode = 0
      tol = 1.0e-12_wp*(maxval(abs(s)) + mc%k)
      if (mohr_yield(mc, s) <= tol) return
      st = s
      ord = order3(s)
      lo = ord(1); mi = ord(2); hi = ord(3)
      ! the usual case first: one plane, chosen by the single-surface rule
      h = st(hi) - mc%sigt + mc%ap*(st(lo) - mc%sp)
      f0 = mc%nphi*st(hi) - st(lo) - mc%k
      f1 = st(hi) - mc%sigt
      if (f0 > 0.0_wp .and. .not. (f1 > 0.0_wp .and. h > 0.0_wp)) then
         t = f0/mc%shear_den
         sn(lo) = st(lo) - t*mc%dm_lo
         sn(mi) = st(mi) - t*mc%dm_mi
         sn(hi) = st(hi) - t*mc%dm_hi
         mode = 1
      else
         t = f1/mc%a1
         sn(lo) = st(lo) - t*mc%a2
         sn(mi) = st(mi) - t*mc%a2
         sn(hi) = mc%sigt
         mode = 2
      end if
      if (mohr_yield(mc, sn) <= tol) then
         s = sn
         return
      end if
      mode = 0
      pn = 0.0_wp
      pm = 0.0_wp
      call shear_plane(1, lo, hi)
      call shear_plane(2, lo, mi)
      call shear_plane(3, mi, hi)
      call tension_plane(4, hi)
      call tension_plane(5, mi)
      call tension_plane(6, lo)
      do k = 1, nplane
         trial(k) = dot_product(pn(:, k), st) - pb(k)
         dm(:, k) = mc%a2*sum(pm(:, k)) + (mc%a1 - mc%a2)*pm(:, k)
      end do
      ! the single-surface rule's choice first
      first = 1
      if (trial(1) <= 0.0_wp .or. (trial(4) > 0.0_wp .and. h > 0.0_wp)) first = 4
      do iset = 0, size(plane_sets, 2)
         if (iset == 0) then
            members = [first, 0, 0]
         else
            members = plane_sets(:, iset)
            if (iset == first) cycle          ! single planes come first, in order
         end if
         m = count(members > 0)
         call try_set(members, m, sn, ok)
         if (ok) then
            s = sn
            mode = 2
            if (any(members(1:m) <= 3)) mode = 1
            return
         end if
      end do
      ! fallback: along the line to an inside point of the hydrostatic axis
      cap = mc%sigt
      if (mc%nphi > 1.0_wp) cap = min(cap, mc%k/(mc%nphi - 1.0_wp))
      x0 = min(sum(st)/3.0_wp, cap - 0.5_wp*mc%k/mc%nphi)
      f0 = mohr_yield(mc, [x0, x0, x0])
      f1 = mohr_yield(mc, st)
      ! convex along the line: inside at t where the chord crosses zero;
      ! then bisection towards the surface
      t = max(0.0_wp, -f0)/(f1 - f0)
      hi_t = 1.0_wp
      do k = 1, 60
         if (hi_t - t <= 1.0e-14_wp) exit
         h = 0.5_wp*(t + hi_t)
         if (mohr_yield(mc, x0 + h*(st - x0)) <= tol) then
            t = h
         else
            hi_t = h
         end if
      end do
      s = x0 + t*(st - x0)
      mode = 1
      if (maxval(s) >= mc%sigt - tol) mode = 2
   contains
      subroutine shear_plane(k, comp, tens)
         integer, intent(in) :: k, comp, tens
         pn(tens, k) = mc%nphi
         pn(comp, k) = -1.0_wp
         pb(k) = mc%k
         pm(tens, k) = mc%npsi
         pm(comp, k) = -1.0_wp
      end subroutine shear_plane

      subroutine tension_plane(k, i)
         integer, intent(in) :: k, i
         pn(i, k) = 1.0_wp
         pb(k) = mc%sigt
         pm(i, k) = 1.0_wp
      end subroutine tension_plane

      !> lambda of the planes in `members` from f_k(s) = 0; consistent when
      !> every lambda >= 0 and the result satisfies every plane.
      subroutine try_set(members, m, sn, ok)
         integer, intent(in) :: members(3), m
         real(wp), intent(out) :: sn(3)
         logical, intent(out) :: ok
         real(wp) :: amat(3, 3), rhs(3), lam(3)
         integer :: r, q
         ok = .false.
         sn = st
         ! a plane the trial satisfies cannot be the only active one
         if (m == 1 .and. trial(members(1)) <= 0.0_wp) return
         do r = 1, m
            do q = 1, m
               amat(r, q) = dot_product(pn(:, members(r)), dm(:, members(q)))
            end do
            rhs(r) = trial(members(r))
         end do
         call solve_small(amat, rhs, m, lam, ok)
         if (.not. ok) return
         ok = .false.
         if (any(lam(1:m) < 0.0_wp)) return
         do q = 1, m
            sn = sn - lam(q)*dm(:, members(q))
         end do
         ok = mohr_yield(mc, sn) <= tol
      end subroutine try_set
   end subroutine mohr_return

   !> Indices of s in ascending order of value.
   pure function order3(s) result(ord)
      real(wp), intent(in) :: s(3)
      integer :: ord(3), t
      ord = [1, 2, 3]
      if (s(ord(2)) < s(ord(1))) then
         t = ord(1); ord(1) = ord(2); ord(2) = t
      end if
      if (s(ord(3)) < s(ord(2))) then
         t = ord(2); ord(2) = ord(3); ord(3) = t
      end if
      if (s(ord(2)) < s(ord(1))) then
         t = ord(1); ord(1) = ord(2); ord(2) = t
      end if
   end function order3

   !> Solution of the m x m system a x = b (m <= 3), Gaussian elimination
   !> with partial pivoting; ok false for a (nearly) singular matrix.
   pure subroutine solve_small(a, b, m, x, ok)
      real(wp), intent(inout) :: a(3, 3), b(3)
      integer, intent(in) :: m
      real(wp), intent(out) :: x(3)
      logical, intent(out) :: ok
      real(wp) :: scale, f, row(3), t
      integer :: i, j, piv
      x = 0.0_wp
      ok = .false.
      scale = maxval(abs(a(1:m, 1:m)))
      if (scale <= 0.0_wp) return
      do i = 1, m
         piv = i - 1 + maxloc(abs(a(i:m, i)), 1)
         if (abs(a(piv, i)) <= 1.0e-10_wp*scale) return
         if (piv /= i) then
            row = a(i, :); a(i, :) = a(piv, :); a(piv, :) = row
            t = b(i); b(i) = b(piv); b(piv) = t
         end if
         do j = i + 1, m
            f = a(j, i)/a(i, i)
            a(j, i:m) = a(j, i:m) - f*a(i, i:m)
            b(j) = b(j) - f*b(i)
         end do
      end do
      do i = m, 1, -1
         x(i) = (b(i) - dot_product(a(i, i + 1:m), x(i + 1:m)))/a(i, i)
      end do
      ok = .true.
   end subroutine solve_small

end module zones_models
