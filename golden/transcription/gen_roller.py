from src import F, vals, T
from gen_common import *
C=L.RE_CONTACT.columns; M=L.RE_MOTION.columns; TR=L.RE_TRACTION.columns; TH=L.RE_THERMAL.columns
RC=('code',)+L.RE_CAGE.columns; RCC=('code',)+L.RACE_CAGE.columns; B=L.BODIES.columns
LD=L.LOADS.columns; AC=L.ACCELERATIONS.columns; SL=L.SLICES.columns
RUNID="Cyl Roller Bearing Geo Mod"
Z='0.000E+00'; U='?'
S0=Step(0, header=dict(tau=0.0,time_s=0.0,outer_race_rot_rev=0.0,inner_race_rot_rev=0.0), run_id=RUNID); S0.markers['header']={}
put(S0,'re_contact',C,[(k,vals(n,1,11)) for k,n in zip(range(1,9),range(3783,3791))])
mo={}
mo[1]=['2.849E+04','1.817E+05','1.800E+02',Z,Z,Z,Z,Z,'3.315E-01',U,U]
rec("roller step 0 re_motion element 1 orbital_velocity_rpm","2.849E+04","decimal point printed as a blank ('2 849E+04'), digits and exponent legible")
rec("roller step 0 re_motion element 1 ang_pos_phi_deg, spin_roll_outer, spin_roll_inner","0.000E+00","garbled ('0 000 -', '0 00000+00') but the mantissa 0.000 is legible: zero whatever the exponent")
mo[2]=['2.849E+04',U,'1.800E+02',U,Z,U,U,U,'1.616E-01',U,U]
mo[3]=['2.849E+04','1.817E+05','1.800E+02',U,Z,U,U,U,'1.452E-02',U,U]
for k,n in zip(range(4,9),range(3799,3804)): mo[k]=vals(n,1,11)
for k in (2,3):
    p=10-k
    for j,c in enumerate(M):
        if mo[k][j]==U and mo[p][j]!=U:
            mo[k][j]=mo[p][j]; rec(f"roller step 0 re_motion element {k} {c}",mo[k][j],f"symmetry: equals element {p} at step 0 (rows k and 10-k are equal in every legible step-0 table)")
put(S0,'re_motion',M,[(k,mo[k]) for k in range(1,9)])
put(S0,'re_traction',TR,[(k,vals(n,1,4)+[U]*7) for k,n in zip(range(1,9),range(3809,3817))])
rec("roller step 0 and step 4000 re_traction: the 4 legible values per row","placed in slip_velocity_outer/inner, trac_coeff_outer/inner","column placement: the text keeps only the leading columns (as in the ball case, where the first 8 of 11 survive); confirmed by the echoed traction curve (A=-8.0E-02, B=9.57239E-01, C=8.58912E+00): (A+B*u)*exp(-C*u)+0.08 gives 4.444E-02 at u=3.388E-02 and 6.926E-02 at u=6.412E-02, as printed")
put(S0,'re_thermal',TH,[(k,vals(n,1,11)) for k,n in zip(range(1,9),range(3821,3829))])
put(S0,'slices_1',SL,[(k,vals(n,1,10)) for k,n in zip(range(1,13),range(3840,3852))],index_name='slice')
# RE/cage table step 0: rows (element,end) in print order; see README for the column-list analysis
rows=[(r,e) for r in range(1,9) for e in (1,2)]
g={rc:[U]*9 for rc in rows}
posz=['2.157E-04','-2.157E-04','2.293E-04','-2.293E-04','2.624E-04','-2.624E-04','2.978E-04']
for i,v in enumerate(posz): g[rows[i]][6]=v
g[rows[7]][6]='-2.978E-04'
rec("roller step 0 re_cage element 4 end 2 contact_pos_z_m","-2.978E-04","printed as '-2 9788-04' (blank for the point, 8 for E); confirmed by the +/- pairs of the column (element 4 end 1 is +2.978E-04, element 6 ends are +/-2.978E-04)")
g[rows[2]][1]='2.243E-05'
for i in (1,2,6,7): g[rows[i]][2]=Z
for i in range(1,7): g[rows[i]][3]=Z; g[rows[i]][4]=Z
for i in range(1,5): g[rows[i]][7]=Z
g[rows[6]][7]=U; g[rows[5]][7]=U
g[rows[7]][7]=Z
g[rows[7]][5]='2.682E-19'
for i in (2,3): g[rows[i]][8]=Z
g[rows[7]][2]=Z
# rows 9-16 from their own lines
for i,n in zip(range(8,16),[3870,3871,3872,3873,3874,3875,3876,3877]):
    f=vals(n,0,8)
    g[rows[i]]=[U]+[U]+f[1:]
g[rows[8]][3]=U; g[rows[8]][4]=U
g[rows[8]][2]=Z
rec("roller step 0 re_cage element 5 end 1 contact_force_N","0.000E+00","garbled '0 000 - 00': mantissa 0.000 legible")
put(S0,'re_cage',RC,[(rc,g[rc]) for rc in rows],multi=True)
put(S0,'race_cage',RCC,[(1,[U,U,'2.052E-01',Z,U,U,U,'3.519E-12']),(2,[U,U,'2.052E-01',Z,Z,'1.000E-04','6.903E-01','3.519E-12'])],index_name='land')
put(S0,'bodies',B,[('Cage',[U]*4+['2.849E+04']+[U]*6),('ORace',[U]*4+[Z]+[U]*6),('IRace',vals(3890,1,11))],index_name='body')
put(S0,'loads',LD,[(lab,vals(n,1,6)) for lab,n in zip(('Cage','Int ORace','Int IRace','Ext ORace','Ext IRace'),range(3903,3908))],index_name='body')
put(S0,'accelerations',AC,[('Cage',vals(3911,1,7)),('ORace',[Z,Z]+[U]*5),('IRace',[Z,Z]+[U]*5)],index_name='body')
rec("roller step 0 accelerations ORace/IRace acc_x_m_s2, acc_y_m_s2","0.000E+00","the two rows are printed together ('ORace IRace  0.000E+00 0.000E+00  0.000E+00 0.000E+00'): two values per column, in row order")
perf=dict(basic_fatigue_life_hours='1.369E+02',modified_fatigue_life_hours='1.369E+02',outer_race_fit_m=Z,
          inner_race_fit_m='5.743E-06',internal_clearance_m='1.774E-05',total_power_loss_W='6.921E+01',
          churning_loss_fraction=Z,exit_fluid_temp_K=Z,hsng_bulk_temp_K='2.940E+02',hsng_outer_temp_K='2.940E+02',
          hsng_inner_temp_K='2.940E+02',shft_bulk_temp_K='2.940E+02',shft_outer_temp_K='2.940E+02',shft_inner_temp_K='2.940E+02')
put(S0,'performance',L.PERFORMANCE_COLUMNS,[('bearing',[perf[c] for c in L.PERFORMANCE_COLUMNS])],index_name='body')
put(S0,'summary',L.SUMMARY.columns,[(0,vals(3919,1,10))],index_name='step')
# ======================= final step 4000 =======================
SF=Step(4000, header=dict(tau=7.618E+01,time_s=5.453E-03,outer_race_rot_rev=0.0,inner_race_rot_rev=6.362E+00), run_id=RUNID); SF.markers['header']={}
put(SF,'re_contact',C,[(1,[U,U,U,'2.453E+02']+[U]*7),(2,['6.172E+02',U,U,'2.453E+02']+[U]*7)]+[(k,vals(n,1,11)) for k,n in zip(range(3,9),range(3932,3938))])
put(SF,'re_motion',M,[(k,vals(n,1,11)) for k,n in zip(range(1,9),range(3940,3948))])
put(SF,'re_traction',TR,[(k,vals(n,1,4)+[U]*7) for k,n in zip(range(1,9),range(3953,3961))])
put(SF,'re_thermal',TH,[(k,vals(n,1,11)) for k,n in zip(range(1,9),range(3965,3973))])
put(SF,'slices_1',SL,[(k,vals(n,1,10)) for k,n in zip(range(1,13),range(3984,3996))],index_name='slice')
fr={}
fr[(1,1)]=[U,U,Z,Z,Z,'1.580E-05','2.317E-04',Z,Z]
fr[(1,2)]=['0','7.651E-05',Z,Z,Z,'-1.605E-05','-2.317E-04',Z,Z]
fr[(2,1)]=[U,U,Z,U,U,'-1.237E-05',U,U,Z]
fr[(2,2)]=['0','4.177E-05',Z,Z,Z,'1.840E-06','-2.171E-04',Z,Z]
fr[(3,1)]=[U,U,Z,Z,Z,'-2.018E-05','2.307E-04',Z,Z]
fr[(3,2)]=[U,U,Z,U,U,'4.973E-05',U,U,'1.731E-15']
fr[(4,1)]=['0','9.051E-05',Z,Z,Z,'-1.731E-05','2.638E-04',Z,Z]
fr[(4,2)]=['0',U,Z,Z,Z,'5.965E-05','-2.638E-04',Z,'2.485E-14']
fr[(5,1)]=[U,U,Z,U,U,'-3.366E-06',U,U,U]
fr[(5,2)]=['0','1.697E-05',Z,Z,Z,'5.161E-05','-2.959E-04',Z,Z]
fr[(6,1)]=[U,U,Z,Z,Z,'1.302E-05','3.083E-04',Z,Z]
fr[(6,2)]=['0','4.851E-05',Z,Z,Z,'-4.076E-07','-3.083E-04',Z,Z]
fr[(7,1)]=['0','3.622E-05',Z,Z,Z,'4.237E-05','2.958E-04',Z,'7.018E-15']
fr[(7,2)]=['0',U,Z,Z,Z,'-1.238E-05','-2.958E-04',Z,Z]
fr[(8,1)]=['0','2.346E-05',Z,Z,Z,'6.466E-05','2.643E-04',Z,Z]
fr[(8,2)]=['0',U,Z,Z,Z,'-1.738E-05','-2.643E-04',Z,Z]
rec("roller step 4000 re_cage geo_int_m of (1,2) (2,2) (4,1) (5,2) (6,2) (7,1) (8,1)","7.651E-05 4.177E-05 9.051E-05 1.697E-05 4.851E-05 3.622E-05 2.346E-05","each number is split across a cell boundary ('1 2 0 7.6 | 51E-05'), all digits legible")
put(SF,'re_cage',RC,[(rc,fr[rc]) for rc in rows],multi=True)
put(SF,'race_cage',RCC,[(1,[U]*8),(2,[U]*8)],index_name='land')
put(SF,'bodies',B,[('Cage',['-5.457E-08']+[U]*10),('ORace',[Z]+[U]*10),('IRace',[Z]+[U]*10)],index_name='body')
rec("roller step 4000 bodies mc_pos_axial_m of Cage/ORace/IRace","-5.457E-08 / 0.000E+00 / 0.000E+00","printed on one line as 'Cage -5.457E-08 ORace 0.000E+00 IRace 0.000E+00'")
put(SF,'loads',LD,[(lab,vals(n,1,6)) for lab,n in zip(('Cage','Int ORace','Int IRace','Ext ORace','Ext IRace'),range(4045,4050))],index_name='body')
put(SF,'accelerations',AC,[('Cage',vals(4053,1,7)),('ORace',[Z,U,U,U,Z,U,U]),('IRace',[Z,U,U,U,Z,U,U])],index_name='body')
rec("roller step 4000 accelerations ORace/IRace acc_x_m_s2, ang_acc_y_rpm_s","0.000E+00","the two rows are printed together, two values per column in row order")
perf=dict(basic_fatigue_life_hours='1.347E+02',modified_fatigue_life_hours='1.347E+02',outer_race_fit_m='6.272E-09',
          inner_race_fit_m='5.732E-06',internal_clearance_m='1.779E-05',total_power_loss_W='9.677E-01',
          churning_loss_fraction=Z,exit_fluid_temp_K='2.939E+02',hsng_bulk_temp_K='2.940E+02',hsng_outer_temp_K='2.940E+02',
          hsng_inner_temp_K='2.940E+02',shft_bulk_temp_K='2.939E+02',shft_outer_temp_K='2.939E+02',shft_inner_temp_K='2.939E+02')
put(SF,'performance',L.PERFORMANCE_COLUMNS,[('bearing',[perf[c] for c in L.PERFORMANCE_COLUMNS])],index_name='body')
put(SF,'summary',L.SUMMARY.columns,[(4000,vals(4060,1,10))],index_name='step')
STEPS=[S0,SF]
TERM=(4000,7.6180E+01)
STATS=dict(minimum_step_size=4.06716E-03,maximum_step_size=4.37787E-02,last_step_size=2.65720E-02,max_truncation=9.93185E-05,total_derivative_calls=43010)
