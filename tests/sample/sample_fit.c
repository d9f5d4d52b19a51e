/* sample_fit.c - how the samplers' polynomial coefficients were derived
 * (include/facet/detail/f32_sample_body.h): interpolation at Chebyshev
 * nodes (near minimax) in long double, coefficients rounded to float, and
 * the maximum relative error of the float-coefficient polynomial measured
 * on a fine grid.  A tool, not a test (the Makefile builds tests/test_*.c
 * only):  cc -O2 tests/sample/sample_fit.c -lm && ./a.out
 *   S(t) = sin(2 pi sqrt t) / sqrt t and C(t) = cos(2 pi sqrt t), t in [0, 1/64]
 *   P(y) = (2^y - 1) / y, y in [-1, 1]
 *   Q(t) = log2((1 + sqrt t) / (1 - sqrt t)) / sqrt t, t in [0, ((sqrt2-1)/(sqrt2+1))^2] */
#include <stdio.h>
#include <math.h>
typedef long double LD;
static LD PI_ = 3.141592653589793238462643383279502884L;
static LD fS(LD t){ LD c=sqrtl(t); return t==0? 2*PI_ : sinl(2*PI_*c)/c; }
static LD fC(LD t){ return cosl(2*PI_*sqrtl(t)); }
static LD fP(LD y){ return y==0? logl(2.0L) : expm1l(y*logl(2.0L))/y; }
static LD fQ(LD t){ LD s=sqrtl(t); return t==0? 2/logl(2.0L) : (logl((1+s)/(1-s))/logl(2.0L))/s; }
static void fit(const char*name, LD(*f)(LD), LD a, LD b, int n, float *out){
  LD A[12][13]; int i,j,k;
  for(i=0;i<=n;i++){ LD x=(a+b)/2+(b-a)/2*cosl(PI_*(2*i+1)/(2*(n+1))); LD p=1;
    for(j=0;j<=n;j++){A[i][j]=p;p*=x;} A[i][n+1]=f(x);}
  for(k=0;k<=n;k++){int piv=k; for(i=k+1;i<=n;i++) if(fabsl(A[i][k])>fabsl(A[piv][k])) piv=i;
    for(j=0;j<=n+1;j++){LD t=A[k][j];A[k][j]=A[piv][j];A[piv][j]=t;}
    for(i=0;i<=n;i++) if(i!=k){LD m=A[i][k]/A[k][k]; for(j=k;j<=n+1;j++) A[i][j]-=m*A[k][j];}}
  for(k=0;k<=n;k++) out[k]=(float)(A[k][n+1]/A[k][k]);
  /* error with float coefficients, exact arithmetic */
  LD mx=0; for(i=0;i<=200000;i++){LD x=a+(b-a)*i/200000.0L; LD p=0; for(j=n;j>=0;j--) p=p*x+out[j];
    LD e=fabsl(p/f(x)-1); if(e>mx) mx=e;}
  printf("%s deg %d: maxrel %.3Le (2^%.2f)\n  ", name, n, mx, (double)log2l(mx));
  for(k=0;k<=n;k++) printf("%.9ef, ", out[k]);
  printf("\n");
}
int main(void){ float c[12];
  fit("S",fS,0,1.0L/64,3,c); fit("S",fS,0,1.0L/64,4,c);
  fit("C",fC,0,1.0L/64,4,c); fit("C",fC,0,1.0L/64,3,c);
  fit("P",fP,-1,1,7,c); fit("P",fP,-1,1,8,c); fit("P",fP,-1,1,9,c);
  LD s0=(sqrtl(2)-1)/(sqrtl(2)+1); fit("Q",fQ,0,s0*s0,3,c); fit("Q",fQ,0,s0*s0,4,c);
  return 0;}
