# Independent check of the potential-energy tooth compliance of
# lib/gearhb/gears/tooth/potential_energy.hpp (bending, shear, axial, Sainsot fillet foundation),
# written without the library: the integrals in the centre-line coordinate x (the library
# integrates in the pressure angle), composite Simpson with N intervals, the half thickness
# y(x) by bisection on the involute radius. Its output is the expected values of
# tests/unit/test_potential_energy.cpp, PotentialEnergy.IndependentImplementation.
# Run: python3 tests/pe_independent_check.py   (about 10 s)
from math import *
def inv(a): return tan(a)-a
def tooth(z,m,a0,x,ha,hf,rho,b,E,nu,rint,r_c,plane_strain=True,N=20000):
    r0=m*z/2; rb=r0*cos(a0); ra=r0+m*(ha+x); rf=r0-m*(hf-x)
    tb=(pi/2+2*x*tan(a0))/z+inv(a0)
    th=lambda r: tb-inv(acos(rb/r))
    Ep=E/(1-nu**2) if plane_strain else E; G=E/(2*(1+nu))
    ac=acos(rb/r_c); tc=th(r_c); xc=r_c*cos(tc); yc=r_c*sin(tc); am=ac-tc
    c=cos(am); s=sin(am)
    def y_of_x(X):
        # on the involute: find r with r cos th(r) = X
        lo=max(rb,rf) ; hi=ra
        if rf<rb and X<=lo*cos(th(lo)):
            return rb*sin(tb)  # straight piece (root below base)
        for i in range(100):
            mid=(lo+hi)/2
            if mid*cos(th(mid))<X: lo=mid
            else: hi=mid
        r=(lo+hi)/2; return r*sin(th(r))
    if rf>=rb: x0=rf*cos(th(rf))
    else: hb=rb*sin(tb); x0=sqrt(rf*rf-hb*hb)
    h=(xc-x0)/N; kb=ks=ka=0
    for i in range(N+1):
        X=x0+i*h; y=y_of_x(X); w=(1 if i in (0,N) else (4 if i%2 else 2))*h/3
        A=2*y*b; I=2/3*y**3*b; M=c*(xc-X)-s*yc
        kb+=w*M*M/(Ep*I); ks+=w*1.2*c*c/(G*A); ka+=w*s*s/(Ep*A)
    tf=(pi/2+2*(hf-rho)*tan(a0)+2*rho/cos(a0))/z; hF=rf/rint
    T=[[-5.574e-5,-1.9986e-3,-2.3015e-4,4.7702e-3,0.0271,6.8045],[60.111e-5,28.100e-3,-83.431e-4,-9.9256e-3,0.1624,0.9086],[-50.952e-5,185.50e-3,0.0538e-4,53.300e-3,0.2895,0.9236],[-6.2042e-5,9.0889e-3,-4.0964e-4,7.8297e-3,-0.1472,0.6904]]
    L,Mm,P,Q=[t[0]/tf**2+t[1]*hF**2+t[2]*hF/tf+t[3]/tf+t[4]*hF+t[5] for t in T]
    Sf=2*rf*tf; u=xc-yc*tan(am)-rf
    kf=c*c/(E*b)*(L*(u/Sf)**2+Mm*u/Sf+P*(1+Q*tan(am)**2))
    return kb,ks,ka,kf
for args in [(50,3e-3,radians(20),0,1,1.25,0.38,0.02,206e9,0.3,0.03,0.075),
             (20,3e-3,radians(20),0,1,1.25,0.38,0.02,206e9,0.3,0.01,0.030),
             (62,2e-3,radians(20),0,1,1.25,0.38,0.02,206e9,0.3,0.0175,0.062)]:
    print(args[0], ["%.10e"%v for v in tooth(*args)])
