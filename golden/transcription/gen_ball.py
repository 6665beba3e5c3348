from src import F, vals, T
from gen_common import *
import re
C=L.RE_CONTACT.columns; M=L.RE_MOTION.columns; TR=L.RE_TRACTION.columns; TH=L.RE_THERMAL.columns
RUNID="Ball Bearing Test Case kGeoMod=100"
S0=Step(0, header=dict(tau=0.0,time_s=0.0,outer_race_rot_rev=0.0,inner_race_rot_rev=0.0), run_id=RUNID)
S0.markers['header']={}
# ---- step 0, re_contact ----
rc={}
rc[1]=['0.000E+00','8.472E+00','?','2.474E+03','?','?','?','?','?','3.149E-04','?']
for k,n in ((2,3167),(3,3168),(4,3169),(7,3172),(16,3180)):
    rc[k]=vals(n,1,11)
rc[5]=['8.000E+01','6.591E+00','?','?','5.460E+02','?','1.235E+09','2.308E-03','1.114E-03','?','1.895E-04']
rc[6]=vals(3171,1,11)
rc[8]=['1.400E+02','4.505E+00','2.993E+01','2.153E+03','3.389E+02','?','1.053E+09','2.265E-03','9.500E-04','?','1.618E-04']
rc[9]=['1.600E+02','4.139E+00','3.016E+01','?','3.064E+02','1.504E+09','1.018E+09','2.258E-03','9.186E-04','2.999E-04','1.565E-04']
rc[10]=['1.800E+02','4.014E+00','3.024E+01','2.127E+03','2.955E+02','1.503E+09','1.006E+09','2.256E-03','9.076E-04','2.996E-04','1.546E-04']
rc[11]=['2.000E+02','4.139E+00','3.016E+01','2.133E+03','3.064E+02','?','1.018E+09','2.258E-03','9.186E-04','?','1.565E-04']
rc[12]=['2.200E+02','4.505E+00','2.993E+01','?','3.389E+02','?','1.053E+09','2.265E-03','9.500E-04','?','1.618E-04']
rc[13]=['2.400E+02','5.101E+00','2.956E+01','?','3.912E+02','1.513E+09','1.105E+09','2.271E-03','9.966E-04','?','1.696E-04']
rc[14]=['2.600E+02','5.816E+00','?','2.218E+03','4.621E+02','1.524E+09','1.168E+09','2.288E-03','1.054E-03','?','1.793E-04']
rc[15]=['2.800E+02','6.591E+00','2.862E+01','?','5.460E+02','?','?','2.308E-03','1.114E-03','?','1.895E-04']
rc[17]=['3.200E+02','7.936E+00','2.778E+01','?','7.142E+02','1.568E+09','1.352E+09','2.352E-03','1.218E-03','?','2.071E-04']
rc[18]=['3.400E+02','?','?','?','7.704E+02','?','?','?','1.249E-03','3.142E-04','?']
# symmetry ball k == ball 20-k (step 0): fill unknowns where the partner is legible
def sym(tab, name, cols, rows=range(2,19), skip=()):
    for k in rows:
        p=20-k
        if p==k: continue
        for j,c in enumerate(cols):
            if c in skip: continue
            if tab[k][j]=='?' and tab[p][j]!='?':
                tab[k][j]=tab[p][j]
                rec(f"ball step 0 {name} element {k} {c}", tab[k][j], f"symmetry: equals element {p} at step 0 (legible)")
sym(rc,'re_contact',C,skip=('orbital_position_deg',))
# stress outer 8 vs 12 conflict -> keep unknown (rows 8 and 12 stay '?', 12 would be filled from nothing since 8 is '?')
assert rc[8][5]=='?' and rc[12][5]=='?'
put(S0,'re_contact',C,[(k,rc[k]) for k in range(1,19)])
# ---- step 0, re_motion ----
rm={}
rm[1]=['8.999E+03','?','-8.452E+00','0.000E+00','0.000E+00','?','-1.958E-02','3.654E-01','1.848E+01','3.165E+01','1.683E-12']
rm[2]=vals(3189,1,11)
blk={c:None for c in range(11)}
# rows 2-8 from the clean cumulative block at line 3195 (all 11 columns hold 7 values)
import re as _re
def block(n):
    out=[]
    for s in F(n)[1:]:
        s=_re.sub(r'\\begin\{array\}\{c\}|\\end\{array\}|\$','',s)
        s=s.replace('\\pm\\!','E+').replace('\\pm','E')
        out.append([t.replace(' ','') for t in _re.findall(r'-?\d\.\d{3}\s*E\s*[-+]\s*\d\d',s)])
    return out
b=block(3195)
assert all(len(c)==7 for c in b)
for r in range(7):
    rm[2+r]=[b[j][r] for j in range(11)]
# row 9: block 3196 (8 rows; wear list lacks one earlier entry -> take last)
b=block(3196)
rm[9]=[b[j][-1] for j in range(11)]
assert rm[9][1]=='7.785E+04'
# row 10: block 3197; columns 5 and 6 (RE ang position) hold 8 entries for 9 rows -> unknown
b=block(3197)
rm[10]=[b[j][-1] for j in range(11)]
rm[10][4]='?'; rm[10][5]='?'
for k in range(11,19):
    rm[k]=list(rm[20-k])
    rec(f"ball step 0 re_motion element {k} (all 11 columns)", "as element %d"%(20-k), f"symmetry: equals element {20-k} (legible rows 2-9; the text's rows 11-18 are garbled LaTeX arrays that repeat the same values)")
put(S0,'re_motion',M,[(k,rm[k]) for k in range(1,19)])
# ---- step 0, re_traction: 8 legible columns; drag, churning moment, net loss lost for every row ----
rt={}
f=F(3211)
lists=[x.split() for x in f[1:9]]
for r in range(3):
    rt[1+r]=[lists[j][r] for j in range(8)]+['?']*3
for k,n in zip(range(4,19),range(3212,3227)):
    rt[k]=vals(n,1,8)+['?']*3
put(S0,'re_traction',TR,[(k,rt[k]) for k in range(1,19)])
# ---- step 0, re_thermal: clean ----
put(S0,'re_thermal',TH,[(k,vals(n,1,11)) for k,n in zip(range(1,19),range(3231,3249))])
# ---- step 0, section 2 ----
RC=('code',)+L.RE_CAGE.columns
cg={}
for k,n in zip(list(range(1,9))+list(range(10,19)),list(range(3261,3269))+list(range(3270,3279))):
    cg[k]=['0']+vals(n,2,8)
cg[9]=['?']+vals(3269,2,8)
put(S0,'re_cage',RC,[(k,cg[k]) for k in range(1,19)])
RCC=('code',)+L.RACE_CAGE.columns
put(S0,'race_cage',RCC,[(1,['0','1.217E-04','0.000E+00','0.000E+00','0.000E+00','?','0.000E+00','0.000E+00']),
                        (2,['0','?','0.000E+00','0.000E+00','0.000E+00','?','0.000E+00','0.000E+00'])],index_name='land')
rec("ball step 0 race_cage land 1 geo_int_m","1.217E-04","legible on the repeated line under the garbled row ('1 2175-04' then '1.217E-04')")
rec("ball step 0 race_cage lands 1-2 force_N, con_angle_deg, contact_loss_W, wear_rate_m3_s (land 2 also att_angle_deg)","0.000E+00","garbled ('0 000 - 00', '0.000100', '0 00000+00') but the mantissa 0.000 is legible, so the value is zero whatever the exponent")
B=L.BODIES.columns
put(S0,'bodies',B,[('Cage',vals(3288,1,11)),
    ('ORace',['0.000E+00','?','?','?','?','?','0.000E+00','?','?','-6.402E+06','?']),
    ('IRace',['?','1.002E-05','?','?','2.000E+04','?','?','?','?','1.184E+08','?'])],index_name='body')
# ---- step 0, section 3 ----
LD=L.LOADS.columns
put(S0,'loads',LD,[('Cage',vals(3304,1,6)),('Int ORace',vals(3305,1,6)),
    ('Int IRace',['-4.495E+03','-4.926E-01','-1.995E+03','-1.004E-01','-6.827E+01','-3.967E-02']),
    ('Ext ORace',['-4.495E+03','?','-1.440E+03','?','-6.726E+01','-4.428E-03']),
    ('Ext IRace',vals(3308,1,6))],index_name='body')
rec("ball step 0 loads Int IRace force_y_N / force_z_N / moment_z_Nm; Ext ORace moment_z_Nm","-4.926E-01, -1.995E+03, -3.967E-02, -4.428E-03","decimal point printed as a blank ('-4 926E-01'), every digit and the exponent legible")
AC=L.ACCELERATIONS.columns
put(S0,'accelerations',AC,[('Cage',vals(3315,1,7)),('ORace',['0.000E+00']*6+['3.230E+02']),('IRace',vals(3318,1,7))],index_name='body')
rec("ball step 0 accelerations ORace (all 7 columns)","0.000E+00 x6, 3.230E+02","the ORace row is printed on the line above its label (line 'ORace' is empty, the row of values precedes it)")
perf=dict(basic_fatigue_life_hours='5.334E+02',modified_fatigue_life_hours='4.460E+03',outer_race_fit_m='1.000E-05',
          inner_race_fit_m='9.918E-07',internal_clearance_m='1.525E-04',total_power_loss_W='5.464E+02',
          churning_loss_fraction='0.000E+00',exit_fluid_temp_K='0.000E+00',hsng_bulk_temp_K='3.230E+02',
          hsng_outer_temp_K='3.230E+02',hsng_inner_temp_K='3.230E+02',shft_bulk_temp_K='3.230E+02',
          shft_outer_temp_K='3.230E+02',shft_inner_temp_K='3.230E+02')
put(S0,'performance',L.PERFORMANCE_COLUMNS,[('bearing',[perf[c] for c in L.PERFORMANCE_COLUMNS])],index_name='body')
put(S0,'summary',L.SUMMARY.columns,[(0,['0.000E+00','0.000E+00','0.000E+00','4.460E+03','5.464E+02','4.570E-01','4.570E-01','4.570E-01','0.000E+00','1.174E-03'])],index_name='step')
# ======================= final step 2500 =======================
SF=Step(2500, header=dict(tau=3.534E+02,time_s=8.612E-02,outer_race_rot_rev=0.0,inner_race_rot_rev=2.871E+01), run_id=RUNID)
SF.markers['header']={}
put(SF,'re_contact',C,[(k,vals(n,1,11)) for k,n in zip(range(1,19),range(3337,3355))])
mo={k:vals(n,1,11) for k,n in zip(range(1,12),range(3362,3373))}
mo[12]=['?']*11
f=F(3374)
lists=[x.split() for x in f[1:]]
for r in range(5):
    row=[]
    for j in range(11):
        lj=lists[j] if j<len(lists) else []
        row.append(lj[r] if len(lj)==5 else '?')
    mo[13+r]=row
mo[18]=['?']*11
put(SF,'re_motion',M,[(k,mo[k]) for k in range(1,19)])
put(SF,'re_traction',TR,[(k,vals(n,1,8)+['?']*3) for k,n in zip(range(1,19),range(3378,3396))])
put(SF,'re_thermal',TH,[(k,vals(n,1,11)) for k,n in zip(range(1,19),range(3401,3419))])
put(SF,'re_cage',RC,[(k,['0']+vals(n,1,8)) for k,n in zip(range(1,19),range(3431,3449))])
put(SF,'race_cage',RCC,[(1,['?','?','?','?','?','1.472E-03','?','?']),(2,['?','?','?','?','?','1.472E-03','?','?'])],index_name='land')
put(SF,'bodies',B,[('Cage',['?']*7+['9.271E-02','?','?','?']),
    ('ORace',['0.000E+00']*7+['0.000E+00','0.000E+00','-9.333E+06','1.792E-12']),
    ('IRace',['?']*7+['0.000E+00','?','?','?'])],index_name='body')
rec("ball step 2500 bodies ang_pos_theta_deg of Cage / ORace / IRace","9.271E-02 / 0.000E+00 / 0.000E+00","the three rows' values are printed together in one cell of the ORace line, in row order")
put(SF,'loads',LD,[('Cage',vals(3470,1,6)),
    ('Int ORace',['4.457E+03','-6.830E+01','1.694E+03','-1.153E-01','5.525E+01','-1.273E+00']),
    ('Int IRace',['?','?','?','?','1.426E+01','?']),
    ('Ext ORace',['-4.457E+03','?','-1.682E+03','?','-5.525E+01','1.273E+00']),
    ('Ext IRace',['4.457E+03','?','1.639E+03','?','-1.426E+01','5.424E+01'])],index_name='body')
rec("ball step 2500 loads Int ORace force_z_N, moment_y_Nm","1.694E+03, 5.525E+01","decimal point printed as a blank ('1 694E+03'), digits and exponent legible")
put(SF,'accelerations',AC,[('Cage',['0.000E+00','0.000E+00','-9.810E+00','0.000E+00','7.266E+00','8.652E-01','3.420E+02']),
    ('ORace',vals(3482,1,7)),('IRace',vals(3483,1,7))],index_name='body')
rec("ball step 2500 accelerations Cage (all 7 columns)","0, 0, -9.810E+00, 0, 7.266E+00, 8.652E-01, 3.420E+02","row printed on the line above the 'Cage' label, whose own line is empty")
perf=dict(basic_fatigue_life_hours='5.515E+02',modified_fatigue_life_hours='4.594E+03',outer_race_fit_m='1.458E-05',
          inner_race_fit_m='-2.484E-05',internal_clearance_m='1.537E-04',total_power_loss_W='5.677E+02',
          churning_loss_fraction='0.000E+00',exit_fluid_temp_K='3.419E+02',hsng_bulk_temp_K='3.468E+02',
          hsng_outer_temp_K='3.457E+02',hsng_inner_temp_K='3.480E+02',shft_bulk_temp_K='3.293E+02',
          shft_outer_temp_K='3.496E+02',shft_inner_temp_K='3.174E+02')
put(SF,'performance',L.PERFORMANCE_COLUMNS,[('bearing',[perf[c] for c in L.PERFORMANCE_COLUMNS])],index_name='body')
put(SF,'summary',L.SUMMARY.columns,[(2500,['8.612E-02','0.000E+00','2.871E+01','?','?','7.024E-02','7.024E-02','?','?','?'])],index_name='step')
rec("ball step 2500 summary time_s, outer/inner_race_rotation_rev","8.612E-02, 0.000E+00, 2.871E+01","garbled ('8 6128-02', '0 000 -'); the same values are legible in the step 2500 header")
rec("ball step 2500 summary re_orbital_vel_ratio, cage_omega_ratio","7.024E-02","garbled '7 0248-02' on one line and '7.0246 02' on its repeat: both show the digits 7.024 and exponent 02")
STEPS=[S0,SF]
TERM=(2500,3.5340E+02)
STATS=dict(minimum_step_size=5.00000E-03,maximum_step_size=1.86684E-01,last_step_size=1.64618E-01,max_truncation=1.72086E-03,total_derivative_calls=21160)
