!> What every dataset of a result file holds, in words: the `long_name` attribute written next
!> to `units` (issue 15), so that k, m, n, eps_a or delta_r can be read without the docs. The
!> text is found from the dataset's name and the group it is in (summary, geometry, normal,
!> tangential, input, failures); doc/app.md lists the same layout.
module shcontact_output_descriptions
   use shcontact_case_result, only: summary_column_help
   implicit none
   private

   public :: dataset_description, describe_dataset

contains

   !> [[dataset_description]] as a subroutine, the form the HDF5 layer calls.
   pure subroutine describe_dataset(path, text)
      !> Dataset path from the root.
      character(len=*), intent(in) :: path
      !> Its description ('' when unknown).
      character(len=:), allocatable, intent(out) :: text
      text = dataset_description(path)
   end subroutine describe_dataset

   !> The description of the dataset at `path` ('' when the layout does not know it).
   pure function dataset_description(path) result(text)
      !> Dataset path from the root, e.g. `cases/000001/patch_1/normal/eps_a`.
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: text
      character(len=:), allocatable :: name, group
      integer :: i, j

      i = index(path, '/', back=.true.)
      name = path(i + 1:)
      group = ''
      if (i > 1) then
         j = index(path(1:i - 1), '/', back=.true.)
         group = path(j + 1:i - 1)
      end if
      if (group(1:min(6, len(group))) == 'patch_' .and. index(path, 'geometry/') > 0) &
         group = 'geometry'
      select case (group)
      case ('summary')
         text = summary_text(name)
      case ('normal')
         text = normal_text(name)
      case ('tangential')
         text = tangential_text(name)
      case ('geometry')
         text = geometry_text(name)
      case ('failures')
         select case (name)
         case ('case'); text = 'number of a case that failed'
         case ('message'); text = 'why the case failed'
         case default; text = ''
         end select
      case ('input', 'profiles')
         select case (name)
         case ('namelist'); text = 'the resolved configuration of the run, as namelist text'
         case ('wheel'); text = 'wheel profile used, (y, z) points in profile coordinates'
         case ('rail'); text = 'rail profile used, (y, z) points in profile coordinates'
         case ('wheel_point', 'rail_point'); text = 'index of the profile point (0, 1, ...): '// &
            'dimension scale of the points of the profile'
         case ('column'); text = 'the columns (y, z) of the profiles: their dimension scale'
         case default; text = ''
         end select
      case default
         text = ''
      end select
   end function dataset_description

   !> A column of /summary: one row per case; inputs then results of the main patch and totals.
   pure function summary_text(name) result(text)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: text
      select case (name)
      case ('case'); text = 'case number (1-based, in the order of the sweep)'
      case ('status'); text = 'status of the case: 0 solved, > 0 failed (see /failures), '// &
         '-1 not run'
      case ('n_patches'); text = 'number of contact patches found by the contact search'
      case ('n_loaded'); text = 'number of contact patches solved (carrying load)'
      case ('main_patch'); text = 'index of the most loaded patch (its group patch_K)'
      ! Swept inputs.
      case ('t_y'); text = 'input: lateral wheelset shift Y_WS'
      case ('roll'); text = 'input: wheelset roll angle'
      case ('yaw'); text = 'input: wheelset yaw angle'
      case ('normal_force'); text = 'input: prescribed normal force on the main patch'
      case ('approach'); text = 'input: prescribed approach of the main patch'
      case ('vertical_force'); text = 'input: prescribed vertical wheel load, shared by all '// &
         'patches'
      case ('friction'); text = 'input: coefficient of friction mu'
      case ('bound'); text = 'input: traction bound of FASTSIM_SH'
      case ('spin_model'); text = 'input: spin model of FASTSIM_SH'
      case ('v_forward'); text = 'input: forward speed of the wheelset'
      case ('v_lateral'); text = 'input: lateral velocity of the wheelset'
      case ('v_vertical'); text = 'input: vertical velocity of the wheelset'
      case ('roll_rate'); text = 'input: roll rate of the wheelset'
      case ('yaw_rate'); text = 'input: yaw rate of the wheelset'
      case ('pitch_rate'); text = 'input: pitch rate of the wheelset (negative rolling forward)'
      ! Results: the column table of the totals and the main patch's values (shcontact_case_result,
      ! shcontact_pipeline_result's patch_columns); nu_x, nu_y, phi are inputs or results.
      case default; text = summary_column_help(name)
      end select
   end function summary_text

   !> A dataset of patch_K/normal: patch totals and the semi-Hertzian strip table.
   pure function normal_text(name) result(text)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: text
      select case (name)
      case ('approach'); text = 'approach delta of the patch (rigid interpenetration)'
      case ('load'); text = 'normal force of the patch, sum of the strip loads N_i'
      case ('area'); text = 'contact area, sum of 2 a_i dy'
      case ('p_max'); text = 'largest strip peak pressure'
      case ('dy'); text = 'strip width'
      case ('y_shift'); text = 'reference point (geometric contact point of the loaded state, '// &
         'where the creepages are given) from the first contact, along the contact plane'
      case ('gamma0'); text = 'contact angle at the reference point (CONTACT sign)'
      case ('r0'); text = 'wheel rolling radius at the reference point'
      case ('is_hertz'); text = '1 when the patch is one Hertz ellipse, else 0 (semi-Hertz strips)'
      case ('ellipse_a'); text = 'Hertz ellipse semi-axis along x (rolling)'
      case ('ellipse_b'); text = 'Hertz ellipse semi-axis along y (lateral)'
      case ('ellipse_y_centre'); text = 'lateral offset of the Hertz ellipse centre from the '// &
         'reference point'
      case ('y'); text = 'strip centre y_i, lateral, from the reference point (field side +)'
      case ('a'); text = 'strip half-length a_i along the rolling direction'
      case ('k'); text = 'strip length ratio k_i = a_i/a_H,i = sqrt(delta_i/delta), 0..1'
      case ('p0'); text = 'strip peak pressure p0_i'
      case ('strip_load'); text = 'strip load N_i = (pi/2) p0_i a_i dy'
      case ('m'); text = 'local Hertz coefficient m_i of the strip'
      case ('n'); text = 'local Hertz coefficient n_i of the strip (n_i/m_i = b_H,i/a_H,i)'
      case ('eps_a'); text = 'local penetration split epsilon_a,i of the strip'
      case ('gamma'); text = 'local contact angle gamma_i of the strip (CONTACT sign)'
      case ('delta_r'); text = 'rolling-radius variation delta_r_i = r_w(y_i) - r0'
      case ('r_wheel'); text = 'local wheel rolling radius r_w,i'
      case default; text = ''
      end select
   end function normal_text

   !> A dataset of patch_K/tangential: forces and the element fields on the strip grid.
   pure function tangential_text(name) result(text)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: text
      select case (name)
      case ('fx'); text = 'longitudinal creep force on the wheel, contact frame'
      case ('fy'); text = 'lateral creep force on the wheel, contact frame (field side +)'
      case ('mz'); text = 'spin moment on the wheel about the reference point'
      case ('fn'); text = 'normal force of the patch'
      case ('fx_norm'); text = 'normalised longitudinal force F_x/(mu F_n)'
      case ('fy_norm'); text = 'normalised lateral force F_y/(mu F_n)'
      case ('coulomb_ratio'); text = 'largest |p|/(mu p_n) over contact elements'
      case ('adhesion_fraction'); text = 'adhesion (stick) area / contact area'
      case ('fy_track'); text = 'lateral force on the wheel in the track frame'
      case ('fz_track'); text = 'vertical force on the wheel in the track frame (down +)'
      case ('x'); text = 'element centre x (rolling direction), element j of strip i'
      case ('y'); text = 'strip centre y_i (lateral, field side +): dimension scale of the '// &
         'strip dimension of the element fields'
      case ('xy'); text = 'element centres (x, y) interleaved: the mesh of the XDMF sidecar '// &
         '(ParaView)'
      case ('dx'); text = 'element length dx_i of each strip'
      case ('element'); text = 'element index j along the strip, 0 at the leading edge: '// &
         'dimension scale of the element dimension of the element fields'
      case ('component'); text = 'the components (x, y) of xy: its dimension scale'
      case ('dy'); text = 'strip width'
      case ('pn'); text = 'normal pressure p_n on the element (semi-ellipsoidal)'
      case ('px'); text = 'longitudinal traction on the wheel'
      case ('py'); text = 'lateral traction on the wheel'
      case ('slip'); text = 'slip magnitude |s| (slip velocity / rolling speed), 0 in adhesion'
      case ('state'); text = 'element state: 0 exterior, 1 adhesion (stick), 2 slip'
      case ('nu_x'); text = 'longitudinal creepage from the wheelset motion at this patch'
      case ('nu_y'); text = 'lateral creepage from the wheelset motion at this patch'
      case ('phi'); text = 'spin creepage from the wheelset motion at this patch'
      case ('x_track'); text = 'longitudinal position of the reference point (track frame)'
      case default; text = ''
      end select
   end function tangential_text

   !> A dataset of a patch geometry group: reference point and tables in y.
   pure function geometry_text(name) result(text)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: text
      select case (name)
      case ('y'); text = 'lateral coordinate of the table points, from the reference point'
      case ('gap'); text = 'undeformed gap g(y) along the reference normal, minus its minimum'
      case ('curv_a'); text = 'longitudinal relative curvature A(y)'
      case ('curv_b'); text = 'lateral relative curvature B(y) = g''''(y)/2, clamped to >= B_min'
      case ('gamma'); text = 'local contact angle gamma(y) (CONTACT sign)'
      case ('r_wheel'); text = 'local wheel rolling radius r_w(y)'
      case ('y_track'); text = 'reference point, lateral track coordinate'
      case ('z_track'); text = 'reference point, vertical track coordinate (down +)'
      case ('y_rail'); text = 'reference point on the rail profile, profile coordinate'
      case ('y_wheel'); text = 'reference point on the wheel profile, profile coordinate'
      case ('gamma0'); text = 'contact angle at the reference point (CONTACT sign)'
      case ('r0'); text = 'wheel rolling radius at the reference point'
      case ('gap0'); text = 'smallest undeformed distance along the reference normal'
      case default; text = ''
      end select
   end function geometry_text

end module shcontact_output_descriptions
