#!/usr/bin/python3
"""Generate the malformed-deck catalogue from base.rad: one deck per fault,
NNN_name.rad (plus the extra files some faults need), and expect.tsv with,
per deck, the file:line the message must name, the card and the field (or,
for faults outside any field, the substring naming the fault).
   cd tests/malformed && ./make_catalogue.py
Each deck is base.rad with exactly one fault; tests/malformed_test.sh runs
`ricochet check` on each and compares."""
import glob
import os

BASE = open('base.rad').read().split('\n')
if BASE[-1] == '':
    BASE.pop()


def hidx(lines, hdr):
    """Index of the header line `hdr` (exact text)."""
    return lines.index(hdr)


def cols(line, c1, c2, text):
    """Put `text` right-justified in columns c1..c2 (1-based, inclusive)."""
    w = c2 - c1 + 1
    line = line.ljust(c2)
    return line[:c1 - 1] + text.rjust(w)[-w:] + line[c2:]


TESTS = []


def T(name, card, field, edit):
    TESTS.append((name, card, field, edit))


def at(hdr, k, c1=None, c2=None, text=None, line=None, expect_k=None):
    """Edit line k after header `hdr` (k = 0 the header, 1 the title or the
    first line of a card without title, ...): columns c1..c2 set to `text`,
    or the whole line replaced by `line`. The expected line is the edited
    one, or the line expect_k after the header."""
    def f(lines):
        h = hidx(lines, hdr)
        i = h + k
        if line is not None:
            lines[i] = line
        else:
            lines[i] = cols(lines[i], c1, c2, text).rstrip()
        return lines, (h + expect_k if expect_k is not None else i), {}
    return f


def delete(hdr, k, n=1, expect_k=0):
    def f(lines):
        h = hidx(lines, hdr)
        del lines[h + k:h + k + n]
        return lines, h + expect_k, {}
    return f


def insert(hdr, k, new, expect_k=None):
    """Insert lines `new` before line k after the header; expected: the first
    inserted line, or line expect_k after the header."""
    def f(lines):
        h = hidx(lines, hdr)
        lines[h + k:h + k] = new
        return lines, (h + k if expect_k is None else h + expect_k), {}
    return f


def before_end(new, expect=0):
    """Insert lines before /END; expected: inserted line number `expect`."""
    def f(lines):
        e = hidx(lines, '/END')
        lines[e:e] = new
        return lines, e + expect, {}
    return f


def rename(hdr, new):
    def f(lines):
        h = hidx(lines, hdr)
        lines[h] = new
        return lines, h, {}
    return f


def whole(text, line):
    """A deck of its own (not derived from base.rad); expected line `line`."""
    def f(lines):
        return text.split('\n'), line - 1, {}
    return f


def chain(*edits, expect=-1):
    """Several edits that make ONE fault (e.g. remove a card and its uses);
    the expected line is that of edit number `expect`."""
    def f(lines):
        res = []
        for e in edits:
            lines, i, _ = e(lines)
            res.append(i)
        return lines, res[expect], {}
    return f


B = '/BEGIN'
F1, F2 = '/FUNCT/1', '/FUNCT/2'
N = '/NODE'
R1, R2, R3 = '/RBODY/1', '/RBODY/2', '/RBODY/3'
G1, G2, G3 = '/GRNOD/NODE/1', '/GRNOD/NODE/2', '/GRNOD/NODE/3'
SE, SP, SC, SB = '/SURF/ELLIPS/1', '/SURF/PLANE/2', '/SURF/CYL/3', '/SURF/BOX/4'
T6, PW = '/INTER/TYPE6/1', '/INTER/POWER/2'
IT, IR = '/INIVEL/TRA/1', '/INIVEL/ROT/2'
GR, BC1, BC2, IV = '/GRAV/1', '/BCS/1', '/BCS/2', '/IMPVEL/1'
SPR, CAT = '/COUPLING/SPRING/1', '/COUPLING/CATENARY/2'
P1, P2, GP = '/PART/1', '/PART/2', '/GRPART/PART/1'
FR, FO = '/FRICTION/1', '/FRIC_ORIENT/1'
JT = '/JOINT/REVOLUTE/1'
RUN, SOL = '/RUN', '/SOLVER'

# ---- /BEGIN
T('begin_invers_real', B, 'field Invers', at(B, 2, 1, 10, '2022.5'))
T('begin_irun_text', B, 'field Irun', at(B, 2, 11, 20, 'one'))
# ---- /FUNCT
T('funct_bad_real', F1, 'field Y', at(F1, 3, 21, 40, '1.0e6x'))
T('funct_nan', F1, 'field X', at(F1, 3, 1, 20, 'nan'))
T('funct_inf', F1, 'field Y', at(F1, 3, 21, 40, '-inf'))
T('funct_hex', F1, 'field Y', at(F1, 3, 21, 40, '0x10'))
T('funct_overflow', F2, 'field Y', at(F2, 3, 21, 40, '1e999'))
T('funct_letterless_exponent', F2, 'field Y', at(F2, 3, 21, 40, '1.5-3'))
T('funct_not_increasing', F2, 'field X', at(F2, 4, 1, 20, '0.5'))
T('funct_equal_abscissae', F2, 'field X', at(F2, 3, 1, 20, '0'))
T('funct_one_point', F1, 'field X', delete(F1, 3))
T('funct_dup_id', F1, 'field fct_ID', rename(F2, F1))
T('funct_no_id', '/FUNCT', 'field fct_ID', rename(F1, '/FUNCT'))
T('funct_comma_extra', F1, 'comma-separated fields', at(F1, 3, line='1,1000000,7'))
# ---- /NODE
T('node_bad_int', N, 'field node_ID', at(N, 1, 1, 10, '1a'))
T('node_zero_id', N, 'field node_ID', at(N, 1, 1, 10, '0'))
T('node_int_overflow', N, 'field node_ID', at(N, 1, 1, 10, '2147483648'))
T('node_real_id', N, 'field node_ID', at(N, 1, 1, 10, '1.0'))
T('node_inf', N, 'field Z', at(N, 1, 51, 70, 'inf'))
T('node_dup', N, 'field node_ID', at(N, 4, 1, 10, '3'))
T('node_unit', '/NODE/3', 'field unit_ID', rename(N, '/NODE/3'))
T('node_tab', '-', 'tab character', at(N, 2, line='         2\t0\t0\t0.02'))
# ---- /RBODY
T('rbody_mass_negative', R1, 'field Mass', at(R1, 2, 41, 60, '-1'))
T('rbody_mass_zero', R1, 'field Mass', at(R1, 2, 41, 60, '0'))
T('rbody_mass_blank', R1, 'field Mass', at(R1, 2, 41, 60, ''))
T('rbody_mass_denormal', R1, 'field Mass', at(R1, 2, 41, 60, '1e-320'))
T('rbody_mass_nan', R1, 'field Mass', at(R1, 2, 41, 60, 'NaN'))
T('rbody_jxx_denormal', R1, 'field Jxx', at(R1, 3, 1, 20, '1e-310'))
T('rbody_jzz_negative', R1, 'field Jzz', at(R1, 3, 41, 60, '-0.001'))
T('rbody_not_positive_definite', R1, 'Jxx..Jxz', at(R1, 4, 1, 20, '0.002', expect_k=3))
T('rbody_skew', R1, 'field Skew_ID', at(R1, 2, 21, 30, '3'))
T('rbody_ispher', R1, 'field Ispher', at(R1, 2, 31, 40, '7'))
T('rbody_icog', R1, 'field ICoG', at(R1, 2, 81, 90, '2'))
T('rbody_node_missing', R1, 'field node_ID', at(R1, 2, 1, 10, '99'))
T('rbody_grnod_missing', R1, 'field grnd_ID', at(R1, 2, 61, 70, '99'))
T('rbody_same_main_node', R2, 'field node_ID', at(R2, 2, 1, 10, '1'))
T('rbody_missing_line', R1, 'expected 3 data lines', delete(R1, 4))
T('rbody_extra_line', R3, 'unexpected data line', insert(R3, 6, ['         1']))
T('rbody_no_id', '/RBODY', 'field rbody_ID', rename(R1, '/RBODY'))
T('rbody_dup_id', R1, 'field rbody_ID', rename(R2, R1))
T('rbody_unit', '/RBODY/1/2', 'field unit_ID', rename(R1, '/RBODY/1/2'))
T('rbody_title_long', R1, 'field title', at(R1, 1, line='x' * 101))
T('rbody_comma_mass', R1, 'field Mass', at(R1, 2, line='1,0,0,0,-1'))
# ---- /GRNOD
T('grnod_negative', G1, 'field node_ID', at(G1, 2, 1, 10, '-1'))
T('grnod_text', G1, 'field node_ID', at(G1, 2, 11, 20, 'two'))
T('grnod_no_subtype', '/GRNOD', 'missing subtype', rename(G1, '/GRNOD'))
T('grnod_node_no_body', G1, 'field node_ID', at(G1, 2, 11, 20, '77'))
T('grnod_dup', G2, 'field grnod_ID', rename(G3, G2))
# ---- /SURF/ELLIPS
T('ellips_skew', SE, 'field skew_ID', at(SE, 2, 1, 10, '1'))
T('ellips_degree', SE, 'field n', at(SE, 2, 11, 20, '3'))
T('ellips_rbody_missing', SE, 'field rbody_ID', at(SE, 2, 21, 30, '9'))
T('ellips_a_negative', SE, 'field a', at(SE, 4, 1, 20, '-0.05'))
T('ellips_not_sphere', SE, 'field b', at(SE, 4, 21, 40, '0.06'))
T('ellips_missing_line', SE, 'expected 3 data lines', delete(SE, 4))
# ---- /SURF/PLANE
T('plane_same_points', SP, 'XM1 YM1 ZM1', at(SP, 3, 41, 60, '0'))
T('plane_rbody_missing', SP, 'field rbody_ID', at(SP, 4, 1, 10, '9'))
T('plane_rbody_negative', SP, 'field rbody_ID', at(SP, 4, 1, 10, '-1'))
T('plane_bad_real', SP, 'field XM', at(SP, 2, 1, 20, '1.2.3'))
# ---- /SURF/CYL
T('cyl_iend', SC, 'field Iend', at(SC, 2, 11, 20, '2'))
T('cyl_zero_axis', SC, 'AX AY AZ', at(SC, 4, 21, 40, '0'))
T('cyl_radius_zero', SC, 'field R', at(SC, 5, 1, 20, '0'))
T('cyl_length_blank', SC, 'field L', at(SC, 5, 21, 40, ''))
T('cyl_rbody_missing', SC, 'field rbody_ID', at(SC, 2, 1, 10, '9'))
# ---- /SURF/BOX
T('box_c_negative', SB, 'field c', at(SB, 4, 41, 60, '-0.025'))
T('box_u_zero', SB, 'UX UY UZ', at(SB, 5, 1, 20, '0'))
T('box_v_parallel', SB, 'VX VY VZ', at(SB, 6, line='                   1                   0                   0'))
T('box_rbody_missing', SB, 'field rbody_ID', at(SB, 2, 1, 10, '9'))
T('surf_dup_id', '/SURF/BOX/3', 'field surf_ID', rename(SB, '/SURF/BOX/3'))
T('surf_seg', '/SURF/SEG/5', 'field node_ID1', before_end(['/SURF/SEG/5', 'segments', '         1'], expect=2))
# ---- /INTER/TYPE6
T('t6_surf_missing', T6, 'field surf_ID2', at(T6, 2, 11, 20, '9'))
T('t6_surf_zero', T6, 'field surf_ID1', at(T6, 2, 1, 10, '0'))
T('t6_fric_negative', T6, 'field Fric', at(T6, 3, 21, 40, '-0.1'))
T('t6_tstop_before_tstart', T6, 'field Tstop', at(T6, 3, 61, 100, '                   2                   1'))
T('t6_istick', T6, 'field Istick', at(T6, 4, 1, 10, '5'))
T('t6_fric_s_without_istick', T6, 'field Fric_s', at(T6, 6, 11, 20, '0.5'))
T('t6_fric_s_negative', T6, 'field Fric_s', chain(at(T6, 4, 1, 10, '1'), at(T6, 6, 11, 20, '-0.5'), expect=1))
T('t6_irs', T6, 'field IRS', at(T6, 4, 11, 20, '3'))
T('t6_inacti', T6, 'field Inacti', at(T6, 4, 31, 40, '3'))
T('t6_fct_ff_missing', T6, 'field fct_IDff', at(T6, 4, 41, 50, '9'))
T('t6_fct_fv_missing', T6, 'field fct_IDfv', at(T6, 4, 51, 60, '9'))
T('t6_fct_ld_missing', T6, 'field fct_IDld', at(T6, 5, 1, 10, '9'))
T('t6_fct_ld_zero', T6, 'field fct_IDld', at(T6, 5, 1, 10, '0'))
T('t6_iform', T6, 'field Iform', at(T6, 5, 11, 20, '3'))
T('t6_stiff_negative', T6, 'field Stiff', at(T6, 6, 21, 40, '-5'))
T('t6_fct_ul_missing', T6, 'field fct_IDul', at(T6, 6, 1, 10, '9'))
T('t6_fct_dv_missing', T6, 'field fct_IDdv', at(T6, 7, 21, 30, '9'))
T('t6_fct_df_missing', T6, 'field fct_IDdf', at(T6, 7, 31, 40, '9'))
T('t6_visc_nan', T6, 'field Visc', at(T6, 7, 1, 20, 'NaN'))
T('t6_missing_line', T6, 'expected 6 data lines', delete(T6, 7))
T('t6_same_body', T6, 'surf_ID1/surf_ID2', at(T6, 2, 11, 20, '1'))
T('t6_unsupported_pair', T6, 'surf_ID1/surf_ID2', at(T6, 2, 1, 10, '2'))  # plane against plane
T('inter_type12', '/INTER/TYPE12/5', 'not supported yet', before_end(['/INTER/TYPE12/5', 'type 12', '         1']))
T('inter_dup_id', '/INTER/POWER/1', 'field inter_ID', rename(PW, '/INTER/POWER/1'))
# ---- /INTER/POWER
T('pw_surf_missing', PW, 'field surf_ID1', at(PW, 2, 1, 10, '9'))
T('pw_fct_stiff_missing', PW, 'field fct_stiff', at(PW, 2, 21, 30, '9'))
T('pw_ispline', PW, 'field Ispline', at(PW, 2, 41, 50, '7'))
T('pw_k_negative', PW, 'field K', at(PW, 3, 1, 20, '-1'))
T('pw_vd_below_vs', PW, 'field v_d', at(PW, 5, 61, 80, '0.005'))
T('pw_comma_extra', PW, 'comma-separated fields', at(PW, 3, line='1e9,1.5,5e8,1,1,9'))
# ---- /INIVEL
T('inivel_grnod_missing', IT, 'field grnod_ID', at(IT, 2, 61, 70, '9'))
T('inivel_skew', IT, 'field skew_ID', at(IT, 2, 71, 80, '1'))
T('inivel_bad_vx', IT, 'field Vx', at(IT, 2, 1, 20, 'fast'))
T('inivel_rot_grnod_missing', IR, 'field grnod_ID', at(IR, 2, 61, 70, '9'))
T('inivel_subtype', '/INIVEL/AXIS/3', 'not supported yet', before_end(['/INIVEL/AXIS/3', 'axis', '']))
# ---- /GRAV
T('grav_dir', GR, 'field DIR', at(GR, 2, 11, 20, 'W'))
T('grav_fct_missing', GR, 'field fct_IDT', at(GR, 2, 1, 10, '9'))
T('grav_grnod_missing', GR, 'field grnod_ID', at(GR, 2, 41, 50, '9'))
T('grav_ascale_negative', GR, 'field Ascale_x', at(GR, 2, 51, 70, '-1'))
T('grav_sensor', GR, 'field sensor_ID', at(GR, 2, 31, 40, '1'))
# ---- /BCS
T('bcs_trarot', BC1, 'field Trarot', at(BC1, 2, 1, 10, '120 000'))
T('bcs_partial_rotation', BC1, 'field Trarot', at(BC1, 2, 1, 10, '110 100'))
T('bcs_grnod_missing', BC2, 'field grnod_ID', at(BC2, 2, 21, 30, '9'))
# ---- /IMPVEL
T('impvel_dir', IV, 'field Dir', at(IV, 2, 11, 20, 'XY'))
T('impvel_fct_missing', IV, 'field fct_IDT', at(IV, 2, 1, 10, '9'))
T('impvel_grnod_missing', IV, 'field grnod_ID', at(IV, 2, 41, 50, '9'))
T('impvel_tstart', IV, 'field Tstart', at(IV, 3, 41, 60, '1'))
T('impvel_held_dof', IV, 'field Dir', at(IV, 2, 11, 20, 'X'))
T('impvel_frame', IV, 'field frame_ID', at(IV, 2, 51, 60, '1'))
# ---- /COUPLING/SPRING
T('spring_same_points', SPR, 'X2 Y2 Z2', at(SPR, 4, 1, 20, '0'))
T('spring_iform', SPR, 'field Iform', at(SPR, 2, 21, 30, '5'))
T('spring_rbody_missing', SPR, 'field rbody_ID1', at(SPR, 2, 1, 10, '9'))
T('spring_both_fixed', SPR, 'rbody_ID1 rbody_ID2', at(SPR, 2, 1, 10, '0'))
T('spring_fct_missing', SPR, 'field fct_ID', at(SPR, 2, 21, 40, '         3         9'))
T('spring_iform3_no_fct', SPR, 'field fct_ID', at(SPR, 2, 21, 30, '3'))
T('spring_kd_negative', SPR, 'field Kd', at(SPR, 5, 21, 40, '-1'))
T('spring_xr_wrong_form', SPR, 'field X_r', insert(SPR, 7, ['                   1                   1']))
# ---- /COUPLING/CATENARY
T('cat_leq_zero', CAT, 'field L_eq', at(CAT, 5, 21, 40, '0'))
T('cat_same_body', CAT, 'field rbody_ID2', at(CAT, 2, 1, 10, '4'))
T('cat_rbody_missing', CAT, 'field rbody_ID2', at(CAT, 2, 11, 20, '9'))
T('cat_no_gravity', CAT, '/GRAV', chain(at(GR, 2, 41, 50, '1'), lambda l: (l, hidx(l, CAT), {})))
T('cat_no_solution', CAT, 'fields Lambda0 L_eq D', at(CAT, 5, 1, 60,
  '              1.5e12                 0.1              1e-300'))
# ---- /PART, /GRPART
T('part_rbody_missing', P1, 'field rbody_ID', at(P1, 3, 1, 10, '9'))
T('part_surf_missing', P1, 'field surf_ID', at(P1, 3, 11, 20, '9'))
T('part_surf_not_carried', P1, 'field surf_ID', at(P1, 3, 11, 20, '2'))
T('part_surf_twice', '/PART/3', 'field surf_ID', before_end(['/PART/3', 'floor again',
  '         0         0         0                   0', '         0         2'], expect=3))
T('part_fixed_no_surface', P2, 'field rbody_ID', at(P2, 3, 11, 20, ''))
T('part_bad_thick', P1, 'field Thick', at(P1, 2, 31, 50, 'thin'))
T('grpart_part_missing', GP, 'field part_ID', at(GP, 2, 1, 10, '9'))
T('grpart_negative', GP, 'field part_ID', at(GP, 2, 1, 10, '-2'))
# ---- /FRICTION, /FRIC_ORIENT
T('fric_ifric', FR, 'field Ifric', at(FR, 2, 1, 10, '5'))
T('fric_iform', FR, 'field Iform', at(FR, 2, 41, 50, '4'))
T('fric_xfreq_range', FR, 'field Xfreq', at(FR, 2, 11, 40, '         1                   2'))
T('fric_fric_negative', FR, 'field Fric', at(FR, 4, 21, 40, '-0.9'))
T('fric_part_missing', FR, 'field part_ID1', at(FR, 5, 21, 30, '9'))
T('fric_grpart_missing', FR, 'field grpart_ID2', at(FR, 5, 11, 20, '9'))
T('fric_group_truncated', FR, 'truncated', delete(FR, 9, expect_k=5))
T('fric_group_no_side', FR, 'grpart_ID1', at(FR, 5, 1, 40, ''))
T('fric_renard_c5', FR, 'field C5', chain(at(FR, 2, 1, 10, '3'),
  at(FR, 3, line='                 0.3                 0.2                 0.5                 0.1                 0.7'),
  at(FR, 4, 1, 20, '0.5'), expect=1))
T('fo_part_missing', FO, 'field part_ID', at(FO, 2, 11, 20, '9'))
T('fo_truncated', FO, 'truncated', delete(FO, 3, expect_k=2))
T('fo_iorth', FO, 'field Iorth', at(FO, 3, 91, 100, '2'))
# ---- /RUN, /SOLVER
T('run_tend_zero', RUN, 'field Tend', at(RUN, 1, 1, 20, '0'))
T('run_dtout_negative', RUN, 'field Dt_out', at(RUN, 1, 21, 40, '-0.01'))
T('run_ev_state', RUN, 'field Ev_state', at(RUN, 1, 41, 50, '3'))
T('run_twice', RUN, 'only one such card', before_end([RUN, '                   2']))
T('run_missing', '-', 'no /RUN card', chain(delete(RUN, 0, 2), lambda l: (l, hidx(l, '/END'), {})))
T('solver_method', SOL, 'field Method', at(SOL, 1, 1, 10, '4'))
# ---- /JOINT
T('joint_body_same', JT, 'field rbody_ID2', at(JT, 2, 11, 20, '4'))
T('joint_body_missing', JT, 'field rbody_ID1', at(JT, 2, 1, 10, '9'))
T('joint_body1_ground', JT, 'field rbody_ID1', at(JT, 2, 1, 10, '0'))
T('joint_point_text', JT, 'field Y', at(JT, 3, 21, 40, 'x'))
T('joint_axis_zero', JT, 'Ax Ay Az', at(JT, 4, line='                   0                   0                   0'))
T('joint_missing_line', JT, 'expected 3 data lines', delete(JT, 4))
T('joint_method_cvode', SOL, 'field Method', at(SOL, 1, 1, 10, '1'))
T('solver_max_order', SOL, 'field Max_order', at(SOL, 1, 11, 20, '6'))
T('solver_rtol_negative', SOL, 'field Rtol', at(SOL, 1, 31, 50, '-1e-6'))
T('solver_atol_negative', SOL, 'field Atol_pos', at(SOL, 2, 1, 20, '-1'))
T('solver_max_steps_real', SOL, 'field Max_steps', at(SOL, 1, 21, 30, '1e5'))
# ---- deck level: lines, headers, cards, includes
T('empty_deck', '-', 'empty file', whole('', 1))
T('comments_only', '-', 'no cards found', whole('# only a comment\n$ and another', 2))
T('data_before_card', '-', 'outside any card', insert(B, 0, ['hello']))
T('unknown_card', '/FOO/1', 'unknown card', before_end(['/FOO/1', 'foo']))
T('planned_card_skew', '/SKEW/1', 'not supported yet', before_end(['/SKEW/1', 'skew']))
T('header_three_numbers', '/RBODY/1/0/3', 'more than two numbers', rename(R1, '/RBODY/1/0/3'))
T('header_keyword_after_id', '/RBODY/1/X', 'keyword after the id', rename(R1, '/RBODY/1/X'))
T('header_empty_keyword', '/RBODY//1', 'empty keyword', rename(R1, '/RBODY//1'))
T('no_rbody', '-', 'no /RBODY card', whole('/RUN\n                   1\n/END', 3))
T('nothing_to_integrate', '-', 'nothing to integrate', whole('\n'.join([
  '/NODE', '         1                   0                   0                   0',
  '/RBODY/1', 'fixed body', '         1                                                 1',
  '               0.001               0.001               0.001', '',
  '/GRNOD/NODE/1', 'body', '         1',
  '/BCS/1', 'all fixed', '   111 111         0         1',
  '/RUN', '                   1', '/END']), 16))
T('binary_byte', '-', 'not a text file', at(R1, 1, line='sph\x01ere'))
T('line_too_long', '-', 'characters: at most 1000', at(R1, 1, line='x' * 1001))
T('ignored_card_then_error', R1, 'field Mass', chain(before_end(['/MAT/LAW1/1', 'steel', '']),
  at(R1, 2, 41, 60, '-1')))


T('spring_stiffness_integral_overflow', SPR, 'field fct_ID', chain(
  at(F2, 2, 21, 40, '1e+308'), at(F2, 3, 21, 40, '-1e+308'), at(F2, 4, 21, 40, '1e+308'),
  at(SPR, 2, 21, 40, '         4         2')))
T('t6_load_slope_denormal', F1, 'field Y', chain(
  at(T6, 3, 21, 40, '0.3'), at(F1, 3, 21, 40, '1e-320'), lambda l: (l, hidx(l, F1) + 3, {})))
T('include_missing', '-', '#include', before_end(['#include no_such_file.rad']))
T('include_empty_name', '-', 'missing file name', before_end(['#include']))
T('include_directory', '-', 'not a regular file', before_end(['#include .']))
T('include_self', '-', 'include cycle', before_end(['#include @SELF@']))
# ---- restitution asked (e_target, V_imp): /INTER/POWER line 6, TYPE6 line 6
T('pw_etarget_above_one', PW, 'field e_target', insert(PW, 6, ['', '                 1.5'], expect_k=7))
T('pw_etarget_with_c', PW, 'field e_target', insert(PW, 6, ['', '                 0.5'], expect_k=7))
T('pw_vimp_text', PW, 'field V_imp', insert(PW, 6, ['', '                 0.5                fast'], expect_k=7))
T('t6_vimp_negative', T6, 'field V_imp', at(T6, 7, 81, 100, '-1'))
# ---- /COUPLING/CONTACT (inserted before /END; the line expected is the faulty one)
CC = '/COUPLING/CONTACT/3'


def cc(l1, l2, l3=None, expect=2):
    lines = [CC, 'contact coupling', l1, l2] + ([l3] if l3 is not None else [])
    return before_end(lines, expect=expect)


CC1 = '         2         4         0         0'
T('cc_d0_zero', CC, 'field d0', cc(CC1, '                   0                 1e6', expect=3))
T('cc_k1_missing', CC, 'field k1', cc(CC1, '                0.01', expect=3))
T('cc_kt_missing', CC, 'field k_t', cc(CC1, '                0.01                 1e6                   0                 0.3', expect=3))
T('cc_iside', CC, 'field Iside', cc('         2         4         5         0', '                0.01                 1e6', expect=2))
T('cc_iest_no_line3', CC, 'field V_imp', cc('         2         4         0         1', '                0.01', expect=0))
T('cc_iest_k1_given', CC, 'field k1', cc('         2         4         0         1', '                0.01                 1e6',
  '                   1               0.002                   0                0.04', expect=3))
T('cc_dmin_above_d0', CC, 'field d_min', cc('         2         4         0         1', '                0.01',
  '                   1                0.02                   0                0.04', expect=4))
T('cc_surf1_analytic', CC, 'field surf_ID1', cc(CC1, '                0.01                 1e6', expect=2))
T('cc_surf1_fixed_segments', CC, 'field surf_ID1', before_end([
  '/NODE', '        20                   5                   5                   0', '        21                   6                   5                   0',
  '        22                   6                   6                   0', '        23                   5                   6                   0',
  '/SURF/SEG/5', 'fixed patch', '         1        20        21        22        23',
  '/SURF/SEG/6', 'second patch', '         1        20        21        22',
  CC, 'contact coupling', '         5         6         0         0', '                0.01                 1e6'], expect=13))


# ---- /JOINT stops (optional line 4: Lim_min Lim_max K_lim C_lim); emitted
# after the include decks, so that the earlier decks keep their numbers
TESTS_LATE = []


def TL(name, card, field, edit):
    TESTS_LATE.append((name, card, field, edit))


def STOP(*vals):
    ln = ''
    for i, v in enumerate(vals):
        if v:
            ln = cols(ln, 20 * i + 1, 20 * i + 20, v)
    return ln


TL('joint_stop_lower_positive', JT, 'field Lim_min', insert(JT, 5, [STOP('0.1', '0.5', '100', '1')]))
TL('joint_stop_angle_range', JT, 'field Lim_max', insert(JT, 5, [STOP('-3', '4', '100', '1')]))
TL('joint_stop_stiffness_blank', JT, 'field K_lim', insert(JT, 5, [STOP('-0.5', '0.5', '', '1')]))
TL('joint_stop_damping_negative', JT, 'field C_lim', insert(JT, 5, [STOP('-0.5', '0.5', '100', '-1')]))
TL('joint_stop_text', JT, 'field Lim_max', insert(JT, 5, [STOP('-0.5', 'x', '100', '1')]))
TL('joint_stop_revolute_one_sided', JT, 'field Lim_max', insert(JT, 5, [STOP('-0.5', '', '100', '1')]))
TL('joint_stop_curve_missing', JT, 'field fct_lim', insert(JT, 5, [cols(STOP('-0.5', '0.5', '', '1'), 81, 90, '99')]))
TL('joint_stop_curve_and_k', JT, 'field K_lim', insert(JT, 5, [cols(STOP('-0.5', '0.5', '100', '1'), 81, 90, '1')]))

# ---- the start (docs/theory.md, "Physics checks of every run"): a sphere
# placed 4 cm inside the floor (its surface centre at z = 0.01, R = 0.05),
# and 3 cm inside it; the message names the interface card's header


def start_overlap(z):
    def f(lines):
        h = hidx(lines, SE)
        lines[h + 3] = cols(lines[h + 3], 41, 60, z).rstrip()
        return lines, hidx(lines, '/INTER/TYPE6/1'), {}
    return f


TL('start_sphere_inside_floor', '/INTER/TYPE6/1', 'overlap at t = 0: penetration 0.04 m', start_overlap('0.01'))
TL('start_sphere_half_inside_floor', '/INTER/TYPE6/1', 'surfaces /SURF/ELLIPS/1 and /SURF/PLANE/2 overlap',
   start_overlap('0.02'))


# ---- /RWALL (a plane 10 m below the scene unless a fault says otherwise)
RW = '/RWALL/PLANE/9'


def RWALL(kind='PLANE', l1=(0, 0, 1, 0), l2=None, m=('0', '0', '-10'), m1=('0', '0', '-9'), extra=(), head=None):
    out = [head or '/RWALL/%s/9' % kind, 'wall', ''.join('%10s' % v for v in l1)]
    out.append(l2 if l2 is not None else '')
    out.append(''.join('%20s' % v for v in m))
    if m1 is not None:
        out.append(''.join('%20s' % v for v in m1))
    return out + list(extra)


TL('rwall_slide_tied', RW, 'field Slide', before_end(RWALL(l1=(0, 1, 1, 0)), expect=2))
TL('rwall_moving_node', RW, 'field node_ID', before_end(RWALL(l1=(1, 0, 2, 0), m=('2', '0', '0')), expect=2))
TL('rwall_moving_mass', RW, 'field Mass', before_end(RWALL(l1=(4, 0, 1, 0), m=('0', '1', '0')), expect=4))
TL('rwall_moving_node_missing', RW, 'field node_ID', before_end(RWALL(l1=(77, 0, 1, 0), m=('2', '1', '0')), expect=2))
TL('rwall_group_missing', RW, 'field grnd_ID1', before_end(RWALL(l1=(0, 0, 99, 0)), expect=2))
TL('rwall_group2_missing', RW, 'field grnd_ID2', before_end(RWALL(l1=(0, 0, 1, 98)), expect=2))
TL('rwall_no_node', RW, 'field grnd_ID1', before_end(RWALL(l1=(0, 0, 0, 0)), expect=2))
TL('rwall_fric_text', RW, 'field fric', before_end(RWALL(l1=(0, 2, 1, 0), l2='%20s%20s' % ('0', 'abc')), expect=3))
TL('rwall_ifq', RW, 'field ifq', before_end(RWALL(l1=(0, 2, 1, 0), l2='%20s%20s%20s%20s%10s' % ('0', '0.3', '0', '0.5', '1')),
                                           expect=3))
TL('rwall_m1_equals_m', RW, 'field XM1 YM1 ZM1', before_end(RWALL(m1=('0', '0', '-10')), expect=5))
TL('rwall_missing_line', RW, 'expected 4 data lines', before_end(RWALL(m1=None), expect=0))
TL('rwall_sphere_diameter', '/RWALL/SPHER/9', 'field Diameter', before_end(RWALL('SPHER', m1=None), expect=3))
TL('rwall_cyl_box', '/RWALL/CYL/9', 'field grnd_ID1',
   before_end(RWALL('CYL', l1=(0, 0, 3, 0), l2='%20s%20s%20s' % ('0', '0', '1'), m1=('1', '0', '-10')), expect=2))
TL('rwall_paral_moving', '/RWALL/PARAL/9', 'field node_ID',
   before_end(RWALL('PARAL', l1=(4, 0, 1, 0), m=('1', '0', '0'), extra=['%20s%20s%20s' % ('1', '0', '-10')]), expect=2))
TL('rwall_paral_collinear', '/RWALL/PARAL/9', 'field XM2 YM2 ZM2',
   before_end(RWALL('PARAL', extra=['%20s%20s%20s' % ('0', '0', '-8')]), expect=6))
TL('rwall_paral_box', '/RWALL/PARAL/9', 'field grnd_ID1',
   before_end(RWALL('PARAL', l1=(0, 0, 3, 0), m1=('1', '0', '-10'), extra=['%20s%20s%20s' % ('0', '1', '-10')]),
              expect=2))
TL('rwall_lagmul', '/RWALL/LAGMUL/9', 'not supported yet', before_end(RWALL(head='/RWALL/LAGMUL/9'), expect=0))
TL('rwall_duplicate', RW, 'duplicate id 9', before_end(RWALL() + RWALL(), expect=6))

# ---- /SENSOR/TIME and its uses (the sphere /RBODY/1 and /INTER/TYPE6/1)
SENS = ['/SENSOR/TIME/4', 'release', '                 0.3']
TL('sensor_tdelay_negative', '/SENSOR/TIME/4', 'field Tdelay', before_end(['/SENSOR/TIME/4', 'release', '               -0.3'],
                                                                            expect=2))
TL('sensor_acce', '/SENSOR/ACCE/4', 'not supported yet', before_end(['/SENSOR/ACCE/4', 'accelerometer', '         1'], expect=0))
TL('sensor_missing_line', '/SENSOR/TIME/4', 'expected 1 data line', before_end(['/SENSOR/TIME/4', 'release'], expect=0))
TL('rbody_sensor_missing', '/RBODY/1', 'field sens_ID', at('/RBODY/1', 2, 11, 20, '9'))
TL('rbody_sensor_held_inivel', '/RBODY/1', 'not supported yet',
   lambda lines: (lambda r: (r[0] + [], r[1], r[2]))(at('/RBODY/1', 2, 11, 20, '4')(before_end(SENS)(lines)[0])))
TL('type6_sensor_missing', T6, 'field Isensor', at(T6, 2, 21, 30, '9'))
TL('type6_sensor_after_tstop', T6, 'field Isensor',
   lambda lines: at(T6, 2, 21, 30, '4')(before_end(['/SENSOR/TIME/4', 'late', '                1e31'])(lines)[0]))
TL('power_sensor_missing', PW, 'field Isensor', at(PW, 2, 61, 70, '9'))


# ---- Radioss spring elements (/SPRING with /PROP/TYPE4), the quadratic
# tetrahedron, moving skews, groups of part groups, a later /IMPVEL start
SPR_PART = ['/PART/9', 'springs', '         9         0']
SPR_ELEM = ['/SPRING/9', '        31         1         2']
PROP4 = ['/PROP/TYPE4/9', 'spring', '                   0', '                 100                   1']
TL('beam_lines_missing', '/PROP/TYPE13/9', 'expected 19 data lines',
   before_end(SPR_PART + ['/PROP/TYPE13/9', 'beam spring', '                   0'] + SPR_ELEM, expect=3))
TL('spring_prop_missing', '/PART/9', 'field prop_ID', before_end(SPR_PART + SPR_ELEM, expect=2))
TL('spring_node3', '/SPRING/9', 'field node_ID3',
   before_end(SPR_PART + PROP4 + ['/SPRING/9', '        31         1         2         3'], expect=8))
TL('spring_free_nodes', '/SPRING/9', 'belong to no /RBODY',
   before_end(['/NODE', '        91                   0                   0                   0',
               '        92                   1                   0                   0'] + SPR_PART + PROP4 +
              ['/SPRING/9', '        31        91        92'], expect=11))
TL('spring_prop_curve', '/PROP/TYPE4/9', 'field fct_ID1',
   before_end(SPR_PART + PROP4 + ['         5'] + SPR_ELEM, expect=7))
TL('spring_prop_rupture', '/PROP/TYPE4/9', 'field dmax',
   before_end(SPR_PART + PROP4 + ['%60s%40s' % ('', '0.02')] + SPR_ELEM, expect=7))
TL('tetra10_node_line_missing', '/TETRA10/9', 'field node_ID1', before_end(['/TETRA10/9', '         7'], expect=1))
TL('skew_mov_aligned', '/SKEW/MOV/9', 'field node_ID1 node_ID2 node_ID3',
   before_end(['/NODE', '        91                   0                   0                   0',
               '        92                   1                   0                   0',
               '        93                   2                   0                   0',
               '/SKEW/MOV/9', 'aligned', '        91        92        93         X'], expect=6))
TL('grpart_grpart_cycle', '/GRPART/GRPART/9', 'form a cycle',
   before_end(['/GRPART/GRPART/8', 'a', '         9', '/GRPART/GRPART/9', 'b', '         8'], expect=5))
TL('impvel_tstart_rotation', '/IMPVEL/1', 'field Tstart', at('/IMPVEL/1', 3, 41, 60, '0.5'))


def T7(l1=None, l2='', l3='', l4=None, l5='', l6=''):
    """/INTER/TYPE7/97 (the nodes of /GRNOD/NODE/1 against the floor
    /SURF/PLANE/2, Istf 1, Stfac 1e5 N/m) with the lines given."""
    l1 = '         1         2         1' if l1 is None else l1
    l4 = STOP('1e5') if l4 is None else l4
    return ['/INTER/TYPE7/97', 'node on the floor', l1, l2, l3, l4, l5, l6]


T7H = '/INTER/TYPE7/97'
TL('type7_istf_default', T7H, 'field Istf', before_end(T7(l1='         1         2         0'), expect=2))
TL('type7_istf_6', T7H, 'field Istf', before_end(T7(l1='         1         2         6'), expect=2))
TL('type7_stmax_below_stmin', T7H, 'field Stmax', before_end(T7(l3=STOP('2e5', '1e5')), expect=4))
TL('type7_stfac_blank', T7H, 'field Stfac', before_end(T7(l4=STOP('', '0.3')), expect=5))
TL('type7_igap_3', T7H, 'field Igap', before_end(T7(l1='         1         2         1         0         3'), expect=2))
TL('type7_ithe', T7H, 'field Ithe', before_end(T7(l1='         1         2         1         1'), expect=2))
TL('type7_icurv', T7H, 'field Icurv', before_end(T7(l1=cols('         1         2         1', 81, 90, '1')), expect=2))
TL('type7_itied', T7H, 'field ITIED', before_end(T7(l2=cols('', 61, 70, '1')), expect=3))
TL('type7_ibc', T7H, 'field IBC', before_end(T7(l5='       111'), expect=6))
TL('type7_inacti', T7H, 'field Inacti', before_end(T7(l5=cols('', 31, 40, '3')), expect=6))
# Inacti 2 on a plane that node 1 lies within the gap (Gapmin 0.2 m) of at
# t = 0: no segments to leave out (found when the model is compiled)
TL('type7_inacti_2_plane', T7H, 'field Inacti',
   before_end(T7(l4=STOP('1e5', '', '0.2'), l5=cols('', 31, 40, '2')), expect=6))
TL('type7_visf', T7H, 'field VISF', before_end(T7(l5=cols('', 61, 80, '0.5')), expect=6))
TL('type7_ifric', T7H, 'field Ifric', before_end(T7(l6='         4'), expect=7))
TL('type7_ifiltr', T7H, 'field Ifiltr', before_end(T7(l6='         0         1'), expect=7))
TL('type7_tstop_before_tstart', T7H, 'field Tstop', before_end(T7(l4=STOP('1e5', '', '', '2', '1')), expect=5))
TL('type7_group_missing', T7H, 'field grnd_IDs', before_end(T7(l1='        99         2         1'), expect=2))
TL('type7_main_sphere', T7H, 'field surf_IDm', before_end(T7(l1='         1         1         1'), expect=2))
TL('type7_friction_missing', T7H, 'field fric_ID', before_end(T7(l6=cols('', 91, 100, '77')), expect=7))
TL('type7_same_body', T7H, 'field grnd_IDs', before_end(
    ['/SURF/PLANE/98', 'carried by the sphere', STOP('0', '0', '0'), STOP('0', '0', '1'), '         1'] +
    T7(l1='         1        98         1'), expect=7))

# ---- /SENSOR/DIST (the sphere's node 1 and the roller's node 2)
def SDIST(nodes='         1         2', dmin='', dmax='0.5', tail=''):
    return ['/SENSOR/DIST/5', 'distance', '                 0.1', nodes + '%20s%20s' % (dmin, dmax) + tail]


SD = '/SENSOR/DIST/5'
TL('sensor_dist_node_missing', SD, 'field node_ID2', before_end(SDIST(nodes='         1        99'), expect=3))
TL('sensor_dist_same_node', SD, 'field node_ID2', before_end(SDIST(nodes='         1         1'), expect=3))
TL('sensor_dist_no_bound', SD, 'field Dmax', before_end(SDIST(dmax=''), expect=3))
TL('sensor_dist_dmax_negative', SD, 'field Dmax', before_end(SDIST(dmax='-1'), expect=3))
TL('sensor_dist_dmin_above_dmax', SD, 'field Dmin', before_end(SDIST(dmin='2', dmax='1'), expect=3))
TL('sensor_dist_tmin', SD, 'field Tmin', before_end(SDIST(tail='%20s' % '-0.01'), expect=3))  # negative
TL('sensor_dist_dflag', SD, 'field Dflag', before_end(SDIST(tail='%20s%10s' % ('', '1')), expect=3))
TL('sensor_dist_missing_line', SD, 'expected 2 data lines', before_end(SDIST()[:3], expect=0))
TL('sensor_dist_fixed_nodes', SD, 'field node_ID2',
   before_end(['/NODE', '        91                   0                   0                   0',
               '        92                   1                   0                   0'] +
              SDIST(nodes='        91        92'), expect=6))
TL('rbody_sensor_dist', '/RBODY/1', 'not supported yet',
   lambda lines: at('/RBODY/1', 2, 11, 20, '5')(before_end(SDIST())(lines)[0]))


# ---- /SENSOR/AND, /SENSOR/OR, /SENSOR/NOT
SLOG = '/SENSOR/AND/8'
TL('sensor_and_input_missing', SLOG, 'field sens_ID2',
   before_end(SENS + [SLOG, 'both', '                   0', '         4         9'], expect=6))
TL('sensor_and_cycle', SLOG, 'form a cycle',
   before_end(SENS + [SLOG, 'both', '                   0', '         4         8'], expect=6))
TL('sensor_or_missing_line', '/SENSOR/OR/8', 'expected 2 data lines',
   before_end(['/SENSOR/OR/8', 'either', '                   0'], expect=0))
TL('sensor_and_input_zero', SLOG, 'field sens_ID1',
   before_end([SLOG, 'both', '                   0', '         0         4'] + SENS, expect=3))
SNOT = '/SENSOR/NOT/8'
TL('sensor_not_self', SNOT, 'field sens_ID1', before_end([SNOT, 'not', '                   0', '         8'], expect=3))
TL('sensor_not_input_missing', SNOT, 'field sens_ID1',
   before_end([SNOT, 'not', '                   0', '         9'], expect=3))
TL('sensor_not_input_zero', SNOT, 'field sens_ID1', before_end([SNOT, 'not', '                   0', '         0'], expect=3))
TL('sensor_not_missing_line', SNOT, 'expected 2 data lines', before_end([SNOT, 'not', '                   0'], expect=0))
TL('sensor_not_cycle', SNOT, 'form a cycle',
   before_end([SNOT, 'a', '                   0', '         7', '/SENSOR/NOT/7', 'b', '                   0', '         8'],
              expect=3))
TL('rbody_sensor_not', '/RBODY/1', 'turns off again',
   lambda lines: at('/RBODY/1', 2, 11, 20, '8')(before_end(SENS + [SNOT, 'not', '                   0', '         4'])(lines)[0]))
TL('type6_sensor_not_disjoint', T6, 'two separate time intervals',
   lambda lines: at(T6, 2, 21, 30, '7')(before_end(SENS + [SNOT, 'not', '                   0', '         4',
                                                          '/SENSOR/TIME/6', 'later', '                 0.5',
                                                          '/SENSOR/OR/7', 'either', '                   0',
                                                          '         8         6'])(lines)[0]))



def T24(l1=None, l2='', l3='', l4=None, l5='', l6=''):
    """/INTER/TYPE24/96 (surf_ID1 /SURF/PLANE/2 and surf_ID2 /SURF/BOX/4 by
    default: the reader's faults come first; Istf 1, Stfac 1e5 N/m) with the
    lines given."""
    l1 = '         2         4         1' if l1 is None else l1
    l4 = STOP('1e5') if l4 is None else l4
    return ['/INTER/TYPE24/96', 'surface to surface', l1, l2, l3, l4, l5, l6]


# two segment surfaces on 4 nodes of no body (fixed)
SEGS24 = ['/NODE', '        91                   0                   0                   5',
          '        92                   1                   0                   5',
          '        93                   1                   1                   5',
          '        94                   0                   1                   5',
          '/SURF/SEG/95', 'upper side', '         1        91        92        93        94',
          '/SURF/SEG/96', 'lower side', '         1        94        93        92        91']
T24H = '/INTER/TYPE24/96'
TL('type24_istf_7', T24H, 'field Istf', before_end(T24(l1='         2         4         7'), expect=2))
TL('type24_stfac_blank', T24H, 'field Stfac', before_end(T24(l4=STOP('', '0.3')), expect=5))
TL('type24_stmax_below_stmin', T24H, 'field Stmax', before_end(T24(l3=STOP('2e5', '1e5')), expect=4))
TL('type24_self_contact', T24H, 'field surf_ID2', before_end(T24(l1='         2         0         1'), expect=2))
TL('type24_same_surface', T24H, 'field surf_ID2', before_end(T24(l1='         2         2         1'), expect=2))
TL('type24_grnd_ids', T24H, 'field grnd_IDs', before_end(T24(l2='         1'), expect=3))
TL('type24_iedge', T24H, 'field Iedge', before_end(T24(l2=cols('', 31, 40, '1')), expect=3))
TL('type24_ipen0', T24H, 'field Ipen0', before_end(T24(l3=cols('', 51, 60, '1')), expect=4))
TL('type24_ipen_max', T24H, 'field Ipen_max', before_end(T24(l3=cols('', 61, 80, '0.01')), expect=4))
TL('type24_ibc', T24H, 'field IBC', before_end(T24(l5='       111'), expect=6))
TL('type24_inacti', T24H, 'field Inacti', before_end(T24(l5=cols('', 31, 40, '2')), expect=6))
TL('type24_tpressfit', T24H, 'field Tpressfit', before_end(T24(l5=cols('', 81, 100, '0.1')), expect=6))
TL('type24_ifric', T24H, 'field Ifric', before_end(T24(l6='         5'), expect=7))
TL('type24_ifiltr', T24H, 'field Ifiltr', before_end(T24(l6='         0         1'), expect=7))
TL('type24_tstop_before_tstart', T24H, 'field Tstop', before_end(T24(l4=STOP('1e5', '', '', '2', '1')), expect=5))
TL('type24_surface_missing', T24H, 'field surf_ID1', before_end(T24(l1='        99         4         1'), expect=2))
TL('type24_surface_plane', T24H, 'field surf_ID1', before_end(T24(l1='         2        96         1'), expect=2))
TL('type24_friction_missing', T24H, 'field fric_ID',
   before_end(SEGS24 + T24(l1='        95        96         1', l6=cols('', 91, 100, '77')), expect=len(SEGS24) + 7))
TL('type24_same_body', T24H, 'field surf_ID2',
   before_end(SEGS24 + T24(l1='        95        96         1'), expect=len(SEGS24) + 2))


def T25(l1=None, l2='', l3='', l4=None, l5='', l6=''):
    """/INTER/TYPE25/95 (surf_ID1 /SURF/PLANE/2, surf_ID2 /SURF/BOX/4 by
    default; Istf 1, Stfac 1e5 N/m) with the lines given."""
    l1 = '         2         4         1' if l1 is None else l1
    l4 = STOP('1e5') if l4 is None else l4
    return ['/INTER/TYPE25/95', 'penalty contact', l1, l2, l3, l4, l5, l6]


T25H = '/INTER/TYPE25/95'
TL('type25_istf_6', T25H, 'field Istf', before_end(T25(l1='         2         4         6'), expect=2))
TL('type25_ithe', T25H, 'field Ithe', before_end(T25(l1='         2         4         1         1'), expect=2))
TL('type25_igap_variable', T25H, 'field Igap', before_end(T25(l1='         2         4         1         0         2'), expect=2))
TL('type25_self_contact', T25H, 'field surf_ID2', before_end(T25(l1='         2         0         1'), expect=2))
TL('type25_ivis2', T25H, 'field IVIS2', before_end(T25(l5=cols('', 21, 30, '-1')), expect=6))
TL('type25_inacti', T25H, 'field Inacti', before_end(T25(l5=cols('', 31, 40, '1')), expect=6))
TL('type25_ifric', T25H, 'field Ifric', before_end(T25(l6='        -2'), expect=7))
TL('type25_iedge_segments', T25H, 'field Iedge',
   before_end(SEGS24 + T25(l1=cols('        95        96         1', 81, 90, '2')), expect=len(SEGS24) + 2))
TL('type25_tpressfit', T25H, 'field Tpressfit', before_end(T25(l4=STOP('1e5', '', '0.1')), expect=5))
TL('type25_dtstif', T25H, 'field DTSTIF', before_end(T25(l6=cols('', 61, 80, '0.5')), expect=7))
TL('type25_box_against_segments', T25H, 'field surf_ID2',
   before_end(SEGS24 + T25(l1='         4        95         1'), expect=len(SEGS24) + 2))

# /LINE/SURF of the plane /SURF/PLANE/2 and of the box /SURF/BOX/4
LINES = ['/LINE/SURF/9102', 'edges of the plane', '         2', '/LINE/SURF/9104', 'edges of the box', '         4']


def T11(l1=None, l2='', l3=None, l4='', l5=''):
    """/INTER/TYPE11/94 (line_IDs /LINE/SURF/9102 of the plane, line_IDm
    /LINE/SURF/9104 of the box by default: the reader's faults come first;
    Istf 1, Stfac 1e5 N/m), after LINES, with the lines given."""
    l1 = '      9102      9104         1' if l1 is None else l1
    l3 = STOP('1e5') if l3 is None else l3
    return LINES + ['/INTER/TYPE11/94', 'edge to edge', l1, l2, l3, l4, l5]


T11H = '/INTER/TYPE11/94'
N = len(LINES)
TL('type11_istf_6', T11H, 'field Istf', before_end(T11(l1='      9102      9104         6'), expect=N + 2))
TL('type11_ithe', T11H, 'field Ithe', before_end(T11(l1='      9102      9104         1         1'), expect=N + 2))
TL('type11_igap_variable', T11H, 'field Igap',
   before_end(T11(l1='      9102      9104         1         0         1'), expect=N + 2))
TL('type11_self_contact', T11H, 'field line_IDm', before_end(T11(l1='      9102         0         1'), expect=N + 2))
TL('type11_stfac_blank', T11H, 'field Stfac', before_end(T11(l3=STOP('', '0.3')), expect=N + 4))
TL('type11_ibc', T11H, 'field IBC', before_end(T11(l4='       111'), expect=N + 5))
TL('type11_visf', T11H, 'field VISF', before_end(T11(l4=cols('', 61, 80, '0.5')), expect=N + 5))
TL('type11_inacti_moved', T11H, 'field Inacti', before_end(T11(l4=cols('', 31, 40, '3')), expect=N + 5))
TL('type11_inacti_nodes', T11H, 'field Inacti', before_end(T11(l4=cols('', 31, 40, '1')), expect=N + 5))
TL('type11_line_missing', T11H, 'field line_IDm', before_end(T11(l1='      9104      9199         1'), expect=N + 2))
TL('type11_line_of_a_plane', T11H, 'field line_IDs', before_end(T11(), expect=N + 2))
TL('type11_line_two_surfaces', T11H, 'field line_IDs',
   before_end(['/LINE/SURF/9105', 'two', '         4         2'] + T11(l1='      9105      9104         1'),
              expect=N + 5))
TL('linesurf_surface_missing', '/LINE/SURF/9106', 'field surf_ID',
   before_end(['/LINE/SURF/9106', 'no surface', '        99'] + T11(l1='      9106      9104         1'), expect=2))
TL('line_edge', '/LINE/EDGE/9107', 'not supported yet', before_end(['/LINE/EDGE/9107', 'free edges', '         4']))


def T19(l1=None, l2='', l3='', l4=None, l5='', l6=''):
    """/INTER/TYPE19/93 (surf_IDs /SURF/PLANE/2, surf_IDm /SURF/BOX/4 by
    default; Istf 1, Stfac 1e5 N/m) with the lines given."""
    l1 = '         2         4         1' if l1 is None else l1
    l4 = STOP('1e5') if l4 is None else l4
    return ['/INTER/TYPE19/93', 'nodes and edges', l1, l2, l3, l4, l5, l6]


T19H = '/INTER/TYPE19/93'
TL('type19_icurv', T19H, 'field Icurv', before_end(T19(l1=cols('         2         4         1', 81, 90, '1')), expect=2))
TL('type19_self_contact', T19H, 'field surf_IDm', before_end(T19(l1='         2         2         1'), expect=2))
TL('type19_ifric', T19H, 'field Ifric', before_end(T19(l6='         7'), expect=7))
TL('type19_surface_plane', T19H, 'field surf_IDs', before_end(T19(), expect=2))
TL('box_reach_overflow', SB, 'field a b c', at(SB, 4, 1, 20, '1e308'))
TL('type19_iedge', T19H, 'field Iedge', before_end(T19(l1=cols('         2         4         1', 51, 60, '3')), expect=2))
TL('type19_inacti_segments', T19H, 'field Inacti', before_end(T19(l5=cols('', 31, 40, '2')), expect=6))


# ---- /PROP/TYPE8 (SPR_GENE) general springs: 19 data lines (line 1, then
# per direction X Y Z RX RY RZ: K C A B D; the curves line; F E Ascale Hscale)
def PROP8(l1='                   0', edit=None):
    lines = ['/PROP/TYPE8/9', 'general spring', l1]
    for _ in range(6):
        lines += ['                 100                   1', '         0', '                   1']
    if edit:
        k, text = edit
        lines[3 + k] = text
    return lines


def GENE(**kw):
    return SPR_PART + PROP8(**kw) + SPR_ELEM


TL('gene_lines_missing', '/PROP/TYPE8/9', 'expected 19 data lines',
   before_end(SPR_PART + ['/PROP/TYPE8/9', 'general spring', '                   0'] + SPR_ELEM, expect=3))
TL('gene_curve', '/PROP/TYPE8/9', 'field fct_ID24', before_end(GENE(edit=(10, '%30s' % '5')), expect=16))
TL('gene_rupture', '/PROP/TYPE8/9', 'field dmax2', before_end(GENE(edit=(4, '%60s%40s' % ('', '-0.02'))), expect=10))
TL('gene_iequil', '/PROP/TYPE8/9', 'field Iequil', before_end(GENE(l1='%20s%20s%50s%10s' % ('0', '0', '', '1')), expect=5))
TL('gene_sensor', '/PROP/TYPE8/9', 'field sens_ID', before_end(GENE(l1='%20s%20s%10s%10s' % ('0', '0', '', '3')), expect=5))
TL('gene_k_negative', '/PROP/TYPE8/9', 'field K3', before_end(GENE(edit=(6, '                  -5')), expect=12))
TL('gene_skew_missing', '/PROP/TYPE8/9', 'field Skew_ID', before_end(GENE(l1='%20s%20s%10s' % ('0', '0', '7')), expect=5))
TL('spring_skew_type4', '/SPRING/9', 'field Skew_ID',
   before_end(SPR_PART + PROP4 + ['/SPRING/9', '        31         1         2' + ' ' * 40 + '%10s' % '7'], expect=8))


# ---- /PROP/TYPE13 (SPR_BEAM): line 1 Mass I Skew_ID sens_ID Isflag Ifail
# Ileng Ifail2, the 18 direction lines of TYPE8, then optional lines
def PROP13(l1='                   0', edit=None):
    lines = PROP8(l1, edit)
    lines[0] = '/PROP/TYPE13/9'
    lines[1] = 'beam spring'
    return lines


TL('beam_ileng', '/PROP/TYPE13/9', 'field Ileng',
   before_end(SPR_PART + PROP13(l1='%20s%20s%40s%10s' % ('0', '0', '', '1')) + SPR_ELEM, expect=5))
TL('beam_curve_missing', '/PROP/TYPE13/9', 'field fct_ID15',
   before_end(SPR_PART + PROP13(edit=(13, '         4')) + SPR_ELEM, expect=19))
TL('spring_skew_mov_bodies', '/SPRING/9', 'field Skew_ID',
   before_end(SPR_PART + ['/SKEW/MOV/7', 'moving', '         1         2         3'] + PROP8() +
              ['/SPRING/9', '        31         1         2' + ' ' * 40 + '%10s' % '7'], expect=28))



def GENE_LOG():
    lines = PROP8()
    lines[3] = '%20s%20s%20s%20s' % ('100', '1', '1', '0.5')
    lines[4] = '         3'
    return SPR_PART + lines + SPR_ELEM


TL('gene_curve_log_rate', '/PROP/TYPE8/9', 'field B1', before_end(GENE_LOG(), expect=6))
TL('gene_rupture_ifail', '/PROP/TYPE8/9', 'field Ifail',
   before_end(SPR_PART + PROP8(l1='%20s%20s%30s%10s' % ('0', '0', '', '1'), edit=(4, '%60s%40s' % ('', '0.02'))) +
              SPR_ELEM, expect=5))

# the law lines Radioss reads after line 6 of a penalty interface: C1..C5
# (Ifric > 0) and C6 (Ifric > 1); Renard's C6 missing; Renard's C5 >= C6
TL('type24_ifric_no_c6', T24H, 'field C6',
   before_end(T24(l6='         3') + ['%20s%20s%20s%20s%20s' % ('0.3', '0.25', '0.4', '0.2', '0.05')], expect=8))
TL('type7_renard_c5', T7H, 'field C5',
   before_end(T7(l6='         3') + ['%20s%20s%20s%20s%20s' % ('0.3', '0.25', '0.4', '0.2', '0.6'), '%20s' % '0.5'],
              expect=8))
TL('type25_ifiltr_xfreq', T25H, 'field Xfreq', before_end(T25(l6='         0         3                  -1'), expect=7))


# ---- skew_ID on /GRAV (a /SKEW/FIX axis; a moving skew stays refused),
# /INIVEL (a skew of any kind; an unknown id refused, as 101_inivel_skew) and /FRIC_ORIENT
TL('grav_skew_missing', GR, 'field skew_ID', at(GR, 2, 21, 30, '9'))
TL('grav_skew_mov', GR, 'field skew_ID',
   lambda lines: at(GR, 2, 21, 30, '9')(before_end(
       ['/NODE', '        91                   0                   0                   0',
        '        92                   1                   0                   0',
        '        93                   0                   1                   0',
        '/SKEW/MOV/9', 'moving', '        91        92        93         X'])(lines)[0]))
TL('inivel_rot_skew_missing', IR, 'field skew_ID', at(IR, 2, 71, 80, '9'))
# /FRIC_ORIENT skew_ID: V from a /SKEW/FIX's X' axis; unknown or moving skews refused
TL('fo_skew_missing', FO, 'field skew_ID', at(FO, 3, 61, 70, '9'))
TL('fo_skew_mov', FO, 'field skew_ID',
   lambda lines: at(FO, 3, 61, 70, '9')(before_end(
       ['/NODE', '        91                   0                   0                   0',
        '        92                   1                   0                   0',
        '        93                   0                   1                   0',
        '/SKEW/MOV/9', 'moving', '        91        92        93         X'])(lines)[0]))
# /BCS skew_ID: all or none of Tx Ty Tz (Rx Ry Rz) only; an unknown skew refused
TL('bcs_skew_partial', BC1, 'field skew_ID', at(BC1, 2, 11, 20, '9'))
TL('bcs_skew_missing', BC1, 'field skew_ID',
   lambda lines: at(BC1, 2, 1, 20, '111 000         9')(lines))


# ---- /SENSOR/INTER (the base deck's /INTER/TYPE6/1 and /INTER/POWER/2)
def SINTER(line2='         1'):
    return ['/SENSOR/INTER/5', 'contact', '                 0.1', line2]


SI = '/SENSOR/INTER/5'
TL('sensor_inter_missing', SI, 'field int_ID', before_end(SINTER('        99'), expect=3))
TL('sensor_inter_zero', SI, 'field int_ID', before_end(SINTER('         0'), expect=3))
TL('sensor_inter_dir_text', SI, 'field DIR', before_end(SINTER('         1        XY'), expect=3))
TL('sensor_inter_dir_tf', SI, 'field DIR', before_end(SINTER('         1        TF%20s%20s' % ('', '10')), expect=3))
TL('sensor_inter_fmax_negative', SI, 'field Fmax', before_end(SINTER('         1        FN%20s%20s' % ('', '-10')), expect=3))
TL('sensor_inter_fmin_negative', SI, 'field Fmin', before_end(SINTER('         1        FN%20s%20s' % ('-1', '10')), expect=3))
TL('sensor_inter_fmin_above_fmax', SI, 'field Fmin',
   before_end(SINTER('         1        FN%20s%20s' % ('20', '10')), expect=3))
TL('sensor_inter_fmin', SI, 'field Fmin', before_end(SINTER('         1        FN%20s' % '20'), expect=3))
TL('sensor_inter_blank_dir_fmax', SI, 'field Fmax', before_end(SINTER('         1%10s%20s%20s' % ('', '', '10')), expect=3))
# Tmin on the first contact (no force bound): not supported yet
TL('sensor_inter_tmin', SI, 'field Tmin', before_end(SINTER('         1%10s%20s%20s%20s' % ('', '', '', '0.01')), expect=3))
TL('sensor_inter_fcut', SI, 'field Fcut',
   before_end(SINTER('         1        FN%20s%20s%20s%20s' % ('', '10', '', '100')), expect=3))
TL('sensor_inter_tdelay_negative', SI, 'field Tdelay',
   before_end(['/SENSOR/INTER/5', 'contact', '                -0.1', '         1'], expect=2))
TL('sensor_inter_missing_line', SI, 'expected 2 data lines', before_end(SINTER()[:3], expect=0))
TL('sensor_inter_self', SI, 'field int_ID',
   lambda lines: before_end(SINTER(), expect=3)(at(T6, 2, 21, 30, '5')(lines)[0]))
TL('type6_sensor_inter_static', T6, 'static analysis',
   lambda lines: at(T6, 2, 21, 30, '5', expect_k=0)(at('/SOLVER', 1, 1, 10, '3')(before_end(SINTER('         2'))(lines)[0])[0]))


# ---- /IMPVEL and /GRAV sensor_ID (a load from its sensor's time on)
TL('impvel_sensor_missing', IV, 'field sensor_ID', at(IV, 2, 31, 40, '9'))
TL('impvel_sensor_rotation_later', IV, 'field sensor_ID',
   lambda lines: at(IV, 2, 31, 40, '4')(before_end(SENS)(lines)[0]))
TL('impvel_sensor_dist_rotation', IV, 'field sensor_ID',
   lambda lines: at(IV, 2, 31, 40, '5')(before_end(SDIST())(lines)[0]))
TL('grav_sensor_not', GR, 'field sensor_ID',
   lambda lines: at(GR, 2, 31, 40, '8')(before_end(SENS + [SNOT, 'not', '                   0', '         4'])(lines)[0]))
TL('grav_sensor_not_inter', GR, 'field sensor_ID',
   lambda lines: at(GR, 2, 31, 40, '8')(before_end(SINTER() + [SNOT, 'not', '                   0', '         5'])(lines)[0]))

def write_all():
    for old in glob.glob('[0-9][0-9][0-9]_*'):
        os.remove(old)
    rows = []
    n = 0

    def emit(name, card, field, lines, idx, files, efile=None):
        nonlocal n
        n += 1
        fname = '%03d_%s.rad' % (n, name)
        pre = '%03d_' % n
        lines = [ln.replace('@SELF@', fname).replace('@N@', pre) for ln in lines]
        with open(fname, 'w') as f:
            f.write('\n'.join(lines) + ('\n' if lines != [''] else ''))
        for k, v in files.items():
            with open(pre + k, 'w') as f:
                f.write('\n'.join(ln.replace('@N@', pre) for ln in v) + '\n')
        rows.append((fname, '%s:%d' % (efile and ('%03d_%s' % (n, efile)) or fname, idx + 1),
                     card, field))

    for name, card, field, edit in TESTS:
        lines, idx, files = edit(list(BASE))
        if name == 'empty_deck':
            lines = ['']
        emit(name, card, field, lines, idx, files)
    # faults inside an included file: the message names that file and line
    inc_cards = ['/NODE', '         5                   0                   0                   1',
                 '         6                   0                   0                   x']
    lines = list(BASE)
    e = hidx(lines, '/END')
    lines[e:e] = ['#include @N@inc_node_inc.rad']
    emit('include_field_error', '/NODE', 'field Z', lines, 2, {'inc_node_inc.rad': inc_cards},
         efile='inc_node_inc.rad')
    lines = list(BASE)
    lines[e:e] = ['#include @N@cycle_a_inc.rad']
    emit('include_cycle', '-', 'include cycle', lines, 0,
         {'cycle_a_inc.rad': ['#include @N@cycle_b_inc.rad'], 'cycle_b_inc.rad': ['#include @N@cycle_a_inc.rad']},
         efile='cycle_b_inc.rad')
    lines = list(BASE)
    lines[e:e] = ['#include @N@nested_missing_inc.rad']
    emit('include_nested_missing', '-', '#include', lines, 1,
         {'nested_missing_inc.rad': ['# a comment', '#include no_such_file.rad']},
         efile='nested_missing_inc.rad')
    for name, card, field, edit in TESTS_LATE:
        lines, idx, files = edit(list(BASE))
        emit(name, card, field, lines, idx, files)
    with open('expect.tsv', 'w') as f:
        f.write('# file\texpected file:line\tcard (- none)\tfield, or the fault\n')
        for r in rows:
            f.write('\t'.join(r) + '\n')
    print('%d decks' % n)


write_all()
