!> Built-in analytic profiles, selectable by name instead of a file (doc/theory.md decision 3):
!>
!> * `S1002`: the EN 13715 wheel from its section definition (doc/theory.md §5.7), y = S, z = F(S),
!>   flange at negative y, flange back at y = −70 mm, origin on the tape circle;
!> * `UIC60`: the 60E1 rail head, upright, origin at the crown top, built from the arcs
!>   R300 / R80 / R13 with tangency and the 1:20 flank (doc/theory.md §5.2, §5.7);
!> * `UIC60-canted`: the same head rotated 1:40 towards the track centre, origin moved to the
!>   highest point of the canted rail, like `MBench_UIC60_v3.prr`.
!>
!> The UIC60 transition points are not taken from the standard (not available to us): they
!> follow from tangency plus two dimensions read off the Manchester sample, which fit them to
!> better than 0.01 mm: the crown arc R300 ends at |y| = 10.5 mm, and the flank is tangent to the
!> R13 corner where the head is 72 mm wide. The head is described down to 37.5 mm below the crown
!> (as in the sample); web and foot never touch a wheel.
!>
!> Profiles are sampled with chords of at most [[builtin_spacing]], plus every section joint, the
!> S1002 flange tip and the crown tops, in the canonical form of [[profile_type]].
module shcontact_profile_builtin
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: lower => to_lower
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_profile_points, only: profile_type, profile_kind_rail, profile_kind_wheel
   implicit none
   private

   public :: builtin_profile, builtin_profile_names, builtin_spacing
   public :: s1002_section, s1002_bounds, s1002_section_count, s1002_tip_s
   public :: uic60_crown_half_width, uic60_head_width, uic60_head_depth, uic60_cant

   !> Names accepted by [[builtin_profile]] (case-insensitive).
   character(len=*), parameter :: builtin_profile_names(3) = &
      [character(len=12) :: 'S1002', 'UIC60', 'UIC60-canted']
   !> Largest chord between consecutive points of a built-in profile (mm).
   real(wp), parameter :: builtin_spacing = 0.1_wp

   !> Number of S1002 sections (A … H).
   integer, parameter :: s1002_section_count = 8
   !> Section k of S1002 spans S from s1002_bounds(k+1) to s1002_bounds(k) (mm, doc/theory.md §5.7).
   real(wp), parameter :: s1002_bounds(s1002_section_count + 1) = [60.0_wp, 32.15796_wp, &
      -26.0_wp, -35.0_wp, -38.426669071_wp, -39.764473993_wp, -49.662510381_wp, &
      -62.764705882_wp, -70.0_wp]
   !> S of the S1002 flange tip (centre of the section G arc).
   real(wp), parameter :: s1002_tip_s = -55.0_wp

   !> UIC60: half-width of the R300 crown arc (mm).
   real(wp), parameter :: uic60_crown_half_width = 10.5_wp
   !> UIC60: head width at the R13/flank tangent points (mm).
   real(wp), parameter :: uic60_head_width = 72.0_wp
   !> UIC60: depth below the crown top where the described head ends (mm).
   real(wp), parameter :: uic60_head_depth = 37.5_wp
   !> Rail inclination of the canted UIC60, 1:40 (rad, doc/theory.md §5.2).
   real(wp), parameter :: uic60_cant = atan(1.0_wp/40.0_wp)

   real(wp), parameter :: r_crown = 300.0_wp, r_side = 80.0_wp, r_corner = 13.0_wp
   !> The flank rises 1 mm laterally per 20 mm vertically.
   real(wp), parameter :: flank_slope = 1.0_wp/20.0_wp

   ! S1002 coefficients (doc/theory.md §5.7).
   real(wp), parameter :: a_a = 1.364323640_wp, b_a = 0.066666667_wp
   real(wp), parameter :: coef_b(0:8) = [0.0_wp, 3.358537058e-2_wp, 1.565681624e-3_wp, &
      2.810427944e-5_wp, 5.844240864e-8_wp, 1.562379023e-8_wp, 5.309217349e-15_wp, &
      5.957839843e-12_wp, 2.646656573e-13_wp]
   real(wp), parameter :: coef_c(0:7) = [4.320221063e3_wp, 1.038384026e3_wp, &
      1.065501873e2_wp, 6.051367875_wp, 2.054332446e-1_wp, 4.169739389e-3_wp, &
      4.687195829e-5_wp, 2.252755540e-7_wp]
   real(wp), parameter :: a_e = 93.576667419_wp, b_e = 2.747477419_wp
   !> Arcs D, F, G, H: F = A + σ√(R² − (S + C)²) with σ = −1 for D, +1 otherwise.
   real(wp), parameter :: arc_a(4) = [16.446_wp, 8.834924130_wp, 16.0_wp, 9.519259302_wp]
   real(wp), parameter :: arc_r(4) = [13.0_wp, 20.0_wp, 12.0_wp, 20.5_wp]
   real(wp), parameter :: arc_c(4) = [26.210665_wp, 58.558326413_wp, 55.0_wp, 49.5_wp]
   real(wp), parameter :: arc_sign(4) = [-1.0_wp, 1.0_wp, 1.0_wp, 1.0_wp]
   !> Arc number (into arc_*) of each section, 0 for the polynomial and straight sections.
   integer, parameter :: arc_of_section(s1002_section_count) = [0, 0, 0, 1, 0, 2, 3, 4]

   !> A piece of a profile: a circular arc y = c_y + R sin φ, z = c_z + σ R cos φ for φ from
   !> φ₀ to φ₁, or a straight segment from p₀ to p₁, or an S1002 section between S₀ and S₁.
   type :: piece_type
      integer :: shape = 0
      real(wp) :: centre(2) = 0.0_wp, radius = 0.0_wp, sigma = 1.0_wp, phi(2) = 0.0_wp
      real(wp) :: p0(2) = 0.0_wp, p1(2) = 0.0_wp
      integer :: section = 0
      real(wp) :: s_range(2) = 0.0_wp
   end type piece_type

   integer, parameter :: shape_arc = 1, shape_line = 2, shape_s1002 = 3

contains

   !> A built-in profile by name (case-insensitive): one of [[builtin_profile_names]].
   subroutine builtin_profile(name, profile, error)
      !> `S1002`, `UIC60` or `UIC60-canted`.
      character(len=*), intent(in) :: name
      !> The profile in canonical form, `source` = `builtin:NAME`.
      type(profile_type), intent(out) :: profile
      !> Unknown name (stat_invalid_input).
      type(error_type), allocatable, intent(out) :: error

      character(len=:), allocatable :: key
      integer :: i

      key = lower(trim(adjustl(name)))
      select case (key)
      case ('s1002')
         call make_profile(s1002_pieces(), profile_kind_wheel, 'S1002', profile)
      case ('uic60')
         call make_profile(uic60_pieces(), profile_kind_rail, 'UIC60', profile)
      case ('uic60-canted')
         call make_profile(uic60_pieces(), profile_kind_rail, 'UIC60-canted', profile)
         call cant_to_highest_point(profile)
      case default
         key = ''
         do i = 1, size(builtin_profile_names)
            key = key//merge(', ', '  ', i > 1)//trim(builtin_profile_names(i))
         end do
         call fatal_error(error, "unknown built-in profile '"//trim(name)// &
            "'; the built-in profiles are "//key(3:)//' (case-insensitive)', stat_invalid_input)
      end select
   end subroutine builtin_profile

   !> Height F(S) and slope dF/dS of S1002 section `section` (1 = A … 8 = H) at S
   !> (doc/theory.md §5.7). Arcs are evaluated with S clamped to their circle; where the tangent
   !> is vertical (S1002 flange back) the slope is returned as ±huge.
   pure subroutine s1002_section(section, s, height, slope)
      !> Section number, 1 (A, field side) to 8 (H, flange back).
      integer, intent(in) :: section
      !> Lateral coordinate S (mm).
      real(wp), intent(in) :: s
      !> F(S), the rise above the tape circle, positive downward (mm).
      real(wp), intent(out) :: height
      !> dF/dS.
      real(wp), intent(out) :: slope

      integer :: k, iarc
      real(wp) :: u, root

      iarc = 0
      if (section >= 1 .and. section <= s1002_section_count) iarc = arc_of_section(section)
      select case (section)
      case (1)
         height = a_a - b_a*s
         slope = -b_a
      case (2)
         ! Alternating signs: A_B − B_B S + C_B S² − … + I_B S⁸.
         height = 0.0_wp
         slope = 0.0_wp
         do k = 8, 1, -1
            height = (height + (-1)**k*coef_b(k))*s
            slope = slope*s + (-1)**k*k*coef_b(k)
         end do
         height = height + coef_b(0)
      case (3)
         ! F = −(A_C + B_C S + … + H_C S⁷).
         height = 0.0_wp
         slope = 0.0_wp
         do k = 7, 1, -1
            height = (height + coef_c(k))*s
            slope = slope*s + k*coef_c(k)
         end do
         height = -(height + coef_c(0))
         slope = -slope
      case (5)
         height = -a_e - b_e*s
         slope = -b_e
      case default
         if (iarc == 0) then
            height = 0.0_wp
            slope = 0.0_wp
            return
         end if
         u = min(max(s + arc_c(iarc), -arc_r(iarc)), arc_r(iarc))
         root = sqrt(max(arc_r(iarc)**2 - u**2, 0.0_wp))
         height = arc_a(iarc) + arc_sign(iarc)*root
         if (root > 0.0_wp) then
            slope = -arc_sign(iarc)*u/root
         else
            slope = -arc_sign(iarc)*sign(huge(1.0_wp), u)
         end if
      end select
   end subroutine s1002_section

   !> S1002 from the field side (S = 60) to the flange back (S = −70); section G is split at
   !> the flange tip so that the tip is a sample point.
   pure function s1002_pieces() result(pieces)
      type(piece_type), allocatable :: pieces(:)
      integer :: k
      allocate (pieces(0))
      do k = 1, s1002_section_count
         if (k == 7) then
            pieces = [pieces, s1002_piece(k, s1002_bounds(k), s1002_tip_s), &
               s1002_piece(k, s1002_tip_s, s1002_bounds(k + 1))]
         else
            pieces = [pieces, s1002_piece(k, s1002_bounds(k), s1002_bounds(k + 1))]
         end if
      end do
   end function s1002_pieces

   !> One S1002 section between S₀ and S₁: arcs are sampled by angle (even spacing up to the
   !> vertical flange back), the other sections by S.
   pure function s1002_piece(section, s0, s1) result(piece)
      integer, intent(in) :: section
      real(wp), intent(in) :: s0, s1
      type(piece_type) :: piece
      integer :: iarc
      iarc = arc_of_section(section)
      if (iarc == 0) then
         piece%shape = shape_s1002
         piece%section = section
         piece%s_range = [s0, s1]
      else
         piece%shape = shape_arc
         piece%centre = [-arc_c(iarc), arc_a(iarc)]
         piece%radius = arc_r(iarc)
         piece%sigma = arc_sign(iarc)
         piece%phi = [arc_angle(s0, iarc), arc_angle(s1, iarc)]
      end if
   end function s1002_piece

   !> Angle φ with S = −C + R sin φ on S1002 arc `iarc`.
   pure real(wp) function arc_angle(s, iarc)
      real(wp), intent(in) :: s
      integer, intent(in) :: iarc
      arc_angle = asin(min(max((s + arc_c(iarc))/arc_r(iarc), -1.0_wp), 1.0_wp))
   end function arc_angle

   !> The upright UIC60 head from the gauge-side flank foot to the field-side one (ascending y),
   !> crown top at the origin. Construction (doc/theory.md §5.2): the R300 crown centred at
   !> (0, 300) ends at |y| = 10.5; each R80 arc is tangent to it (centre on the line from the
   !> crown centre through the joint, 220 mm from it); each R13 corner is tangent inside the R80
   !> arc (centres 67 mm apart) and tangent to the 1:20 flank, which touches it where the head
   !> is 72 mm wide. The crown is split at its top and at ±α (α = atan 1/40): +α becomes the
   !> highest point after canting; −α keeps the samples symmetric.
   pure function uic60_pieces() result(pieces)
      type(piece_type), allocatable :: pieces(:)
      real(wp) :: theta1, c_side(2), c_corner(2), normal(2), t_side, t_corner, t_flank
      real(wp) :: foot(2), tangent(2)
      type(piece_type) :: half(4)

      ! Crown/side joint: crown angle θ₁ with 300 sin θ₁ = 10.5.
      theta1 = asin(uic60_crown_half_width/r_crown)
      c_side = [0.0_wp, r_crown] + (r_crown - r_side)*[sin(theta1), -cos(theta1)]
      ! Outward normal of the field-side flank y = y_t + (z − z_t)/20.
      normal = [1.0_wp, -flank_slope]/sqrt(1.0_wp + flank_slope**2)
      c_corner(1) = 0.5_wp*uic60_head_width - r_corner*normal(1)
      c_corner(2) = c_side(2) - sqrt((r_side - r_corner)**2 - (c_corner(1) - c_side(1))**2)
      tangent = c_corner + r_corner*normal
      foot = [tangent(1) + flank_slope*(uic60_head_depth - tangent(2)), uic60_head_depth]
      ! Angles from the upward direction: y = c_y + R sin φ, z = c_z − R cos φ.
      t_side = theta1
      t_corner = atan2(c_corner(1) - c_side(1), c_side(2) - c_corner(2))
      t_flank = atan2(normal(1), -normal(2))

      ! Field side, from the crown point that becomes the highest one after canting.
      half(1) = arc_piece([0.0_wp, r_crown], r_crown, uic60_cant, t_side)
      half(2) = arc_piece(c_side, r_side, t_side, t_corner)
      half(3) = arc_piece(c_corner, r_corner, t_corner, t_flank)
      half(4)%shape = shape_line
      half(4)%p0 = tangent
      half(4)%p1 = foot

      pieces = [mirrored(half(4)), mirrored(half(3)), mirrored(half(2)), mirrored(half(1)), &
         arc_piece([0.0_wp, r_crown], r_crown, -uic60_cant, 0.0_wp), &
         arc_piece([0.0_wp, r_crown], r_crown, 0.0_wp, uic60_cant), half]
   end function uic60_pieces

   pure function arc_piece(centre, radius, phi0, phi1) result(piece)
      real(wp), intent(in) :: centre(2), radius, phi0, phi1
      type(piece_type) :: piece
      piece%shape = shape_arc
      piece%centre = centre
      piece%radius = radius
      piece%sigma = -1.0_wp
      piece%phi = [phi0, phi1]
   end function arc_piece

   !> The piece mirrored about y = 0 and run in the opposite direction.
   pure function mirrored(piece) result(image)
      type(piece_type), intent(in) :: piece
      type(piece_type) :: image
      image = piece
      select case (piece%shape)
      case (shape_arc)
         image%centre(1) = -piece%centre(1)
         image%phi = -piece%phi([2, 1])
      case (shape_line)
         image%p0 = [-piece%p1(1), piece%p1(2)]
         image%p1 = [-piece%p0(1), piece%p0(2)]
      end select
   end function mirrored

   !> Sample the pieces in order into a profile: each piece from its start (included) to its
   !> end (excluded, except for the last piece), chords at most [[builtin_spacing]].
   pure subroutine make_profile(pieces, kind, name, profile)
      type(piece_type), intent(in) :: pieces(:)
      integer, intent(in) :: kind
      character(len=*), intent(in) :: name
      type(profile_type), intent(out) :: profile
      real(wp), allocatable :: y(:), z(:)
      integer :: ip, n, total

      total = 1
      do ip = 1, size(pieces)
         total = total + piece_intervals(pieces(ip))
      end do
      allocate (y(total), z(total))
      n = 0
      do ip = 1, size(pieces)
         call sample_piece(pieces(ip), ip == size(pieces), y, z, n)
      end do
      profile%source = 'builtin:'//name
      profile%kind = kind
      profile%y = y(:n)
      profile%z = z(:n)
      allocate (profile%kink(n), source=.false.)
      call profile%update_arc_length()
   end subroutine make_profile

   !> Number of intervals that keep every chord of the piece below [[builtin_spacing]].
   pure integer function piece_intervals(piece) result(n)
      type(piece_type), intent(in) :: piece
      real(wp) :: length
      select case (piece%shape)
      case (shape_arc)
         length = piece%radius*abs(piece%phi(2) - piece%phi(1))
      case (shape_line)
         length = norm2(piece%p1 - piece%p0)
      case default
         length = abs(piece%s_range(2) - piece%s_range(1))*max_stretch(piece)
      end select
      n = max(1, ceiling(length/builtin_spacing))
   end function piece_intervals

   !> Largest √(1 + F'²) over an S1002 polynomial or straight section: uniform steps in S of
   !> h / max√(1 + F'²) keep every chord below h. Sampled at 1000 points plus a 2 % margin.
   pure real(wp) function max_stretch(piece)
      type(piece_type), intent(in) :: piece
      integer, parameter :: n_probe = 1000
      integer :: k
      real(wp) :: s, f, df
      max_stretch = 1.0_wp
      do k = 0, n_probe
         s = piece%s_range(1) + (piece%s_range(2) - piece%s_range(1))*real(k, wp)/n_probe
         call s1002_section(piece%section, s, f, df)
         max_stretch = max(max_stretch, sqrt(1.0_wp + df**2))
      end do
      max_stretch = 1.02_wp*max_stretch
   end function max_stretch

   pure subroutine sample_piece(piece, with_end, y, z, n)
      type(piece_type), intent(in) :: piece
      logical, intent(in) :: with_end
      real(wp), intent(inout) :: y(:), z(:)
      integer, intent(inout) :: n
      integer :: j, m
      real(wp) :: t, phi, slope

      m = piece_intervals(piece)
      do j = 0, merge(m, m - 1, with_end)
         t = real(j, wp)/m
         n = n + 1
         select case (piece%shape)
         case (shape_arc)
            phi = piece%phi(1) + t*(piece%phi(2) - piece%phi(1))
            y(n) = piece%centre(1) + piece%radius*sin(phi)
            z(n) = piece%centre(2) + piece%sigma*piece%radius*cos(phi)
         case (shape_line)
            y(n) = piece%p0(1) + t*(piece%p1(1) - piece%p0(1))
            z(n) = piece%p0(2) + t*(piece%p1(2) - piece%p0(2))
         case default
            y(n) = piece%s_range(1) + t*(piece%s_range(2) - piece%s_range(1))
            call s1002_section(piece%section, y(n), z(n), slope)
         end select
      end do
   end subroutine sample_piece

   !> Rotate the upright rail 1:40 towards the track centre and move the origin to the highest
   !> point: the crown point at angle α = atan(1/40) on the field side of the top, which then
   !> lies straight above the crown centre (doc/theory.md §5.2).
   pure subroutine cant_to_highest_point(profile)
      type(profile_type), intent(inout) :: profile
      real(wp) :: c, s, apex(2), top(2), y_new
      integer :: i
      c = cos(uic60_cant)
      s = sin(uic60_cant)
      apex = [r_crown*sin(uic60_cant), r_crown*(1.0_wp - cos(uic60_cant))]
      top = [c*apex(1) + s*apex(2), -s*apex(1) + c*apex(2)]
      do i = 1, profile%size()
         y_new = c*profile%y(i) + s*profile%z(i)
         profile%z(i) = -s*profile%y(i) + c*profile%z(i) - top(2)
         profile%y(i) = y_new - top(1)
      end do
      profile%source = 'builtin:UIC60-canted'
      call profile%update_arc_length()
   end subroutine cant_to_highest_point


end module shcontact_profile_builtin
