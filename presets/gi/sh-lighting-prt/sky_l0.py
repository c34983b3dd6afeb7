# The expectation of the case sky-projects-to-its-l0: the default sky of env.glsl (env_radiance_fixed,
# sun_dir [-0.7, 0.5, -0.3]) projected onto y_00 on the host by the midpoint rule in (z, phi).
# python3 sky_l0.py  (~7 s); the last line is the sun lobe green nudge the case must see.
import math
sd=(-0.7,0.5,-0.3); l=math.sqrt(sum(c*c for c in sd)); sd=tuple(c/l for c in sd)
def clamp(x,a,b): return min(max(x,a),b)
def smooth(e0,e1,x):
    t=clamp((x-e0)/(e1-e0),0,1); return t*t*(3-2*t)
def L(w,green=4.8):
    up=w[1]; t=clamp(up,0,1)
    sky=[0.35+(0.1-0.35)*t, 0.4+(0.2-0.4)*t, 0.5]
    ground=[0.18,0.14,0.1]; k=smooth(-0.2,0.1,up)
    base=[ground[i]+(sky[i]-ground[i])*k for i in range(3)]
    s=max(w[0]*sd[0]+w[1]*sd[1]+w[2]*sd[2],0.0)
    p=s**8
    return [base[0]+6.0*p, base[1]+green*p, base[2]+3.2*p]
NZ=1200; NP=2400
acc=[0,0,0]; accg=0; acc1=[0,0,0]
for i in range(NZ):
    z=-1+(i+0.5)*2/NZ; r=math.sqrt(1-z*z)
    for j in range(NP):
        ph=(j+0.5)*2*math.pi/NP
        w=(r*math.cos(ph), z, r*math.sin(ph))
        v=L(w)
        for c in range(3): acc[c]+=v[c]; acc1[c]+=v[c]*w[1]
dw=(2/NZ)*(2*math.pi/NP)
Y00=0.5*math.sqrt(1/math.pi); Y1=math.sqrt(3/(4*math.pi))
print('c0',[a*dw*Y00 for a in acc]); print('c(1,0)*y',[a*dw*Y1 for a in acc1])
print('mut green delta', 0.48*Y00*2*math.pi/9)
