/* pm2dof generated code for model 'rrr4_platform_design' (4 legs, friction 'coulomb_viscous').
 * Written by `pm2dof derive` from the model file; do not edit.
 *
 * Every function follows CasADi's C API: int f(const double** arg, double** res,
 * long long* iw, double* w, int mem), with work sizes from f_work(). All inputs and
 * outputs are dense; matrices are stored ROW-MAJOR (flattened row by row). SI units.
 *
 * q     = [qa_1..qa_4, qb_1..qb_4]  absolute joint angles, rad (eq. 3 order)
 * qa    = [qa_1..qa_4]  measured active angles, rad
 * xe    = [x, y, phi] pose (m, angles in rad);  xed, xrd, xrdd: its rates and accelerations
 * theta = [alpha1, alpha2, alpha3, alpha4, beta1, beta2, beta3, beta4, gamma1, gamma2, gamma3, gamma4, m_p, mx_p, my_p, I_p, fv1, fv2, fv3, fv4, fc1, fc2, fc3, fc4]
 * sing  = [the legs' type I measure (min over the legs), sigma_min of S with unit rows
 *         over sqrt(n/3) (type II, actuation)]
 * design = [la, lb]  the model file's [design] variables, m: the last input of every function that lists it
 *
 * Functions (inputs -> outputs, element counts):
 *   rrr4_platform_design_ik(xe[3], design[2]) -> (q[8])
 *   rrr4_platform_design_fk(qa[4], design[2]) -> (xe[3], residual[4])
 *   rrr4_platform_design_H(q[8], design[2]) -> (H[8])
 *   rrr4_platform_design_A(q[8], design[2]) -> (A[64])
 *   rrr4_platform_design_singularity(q[8]) -> (sin_ab[4])
 *   rrr4_platform_design_singularity_measures(q[8], design[2]) -> (sing[2])
 *   rrr4_platform_design_W(q[8], design[2]) -> (W[24], sing[2])
 *   rrr4_platform_design_S(q[8], design[2]) -> (S[12], sing[2])
 *   rrr4_platform_design_Wdot(q[8], xed[3], design[2]) -> (Wdot[24], sing[2])
 *   rrr4_platform_design_M(q[8], theta[24]) -> (M[64])
 *   rrr4_platform_design_C(q[8], qd[8], theta[24]) -> (C[64])
 *   rrr4_platform_design_Me(q[8], theta[24], design[2]) -> (Me[9], sing[2])
 *   rrr4_platform_design_Ce(q[8], xed[3], theta[24], design[2]) -> (Ce[9], sing[2])
 *   rrr4_platform_design_StF(q[8], xed[3], theta[24], design[2]) -> (StF[3], sing[2])
 *   rrr4_platform_design_Y(q[8], xed[3], xrd[3], xrdd[3], design[2]) -> (Y[72], sing[2])
 *   rrr4_platform_design_torque_splits(q[8], u[3], tau_max[4], preload_sign[4], preload[4], design[2]) -> (tau_min_norm[4], tau_min_max[4], min_max_ratio[1], tau_preload[4], preload_mode[1], sing[2])
 *   rrr4_platform_design_forward_dynamics(xe[3], xed[3], tau_a[4], theta[24], design[2]) -> (xedd[3], sing[2])
 *   rrr4_platform_design_na_step(state[30], qa[4], xd[3], xd_dot[3], xd_ddot[3], params[48], design[2]) -> (tau_a[4], state_next[30], status[1], diag[14])
 *   rrr4_platform_design_na_minmax_step(state[30], qa[4], xd[3], xd_dot[3], xd_ddot[3], params[48], design[2]) -> (tau_a[4], state_next[30], status[1], diag[14])
 *   rrr4_platform_design_na_preload_step(state[30], qa[4], xd[3], xd_dot[3], xd_ddot[3], params[48], design[2]) -> (tau_a[4], state_next[30], status[1], diag[14])
 *   rrr4_platform_design_na_proj_step(state[30], qa[4], xd[3], xd_dot[3], xd_ddot[3], params[48], design[2]) -> (tau_a[4], state_next[30], status[1], diag[14])
 *   rrr4_platform_design_na_proj_minmax_step(state[30], qa[4], xd[3], xd_dot[3], xd_ddot[3], params[48], design[2]) -> (tau_a[4], state_next[30], status[1], diag[14])
 *   rrr4_platform_design_na_proj_preload_step(state[30], qa[4], xd[3], xd_dot[3], xd_ddot[3], params[48], design[2]) -> (tau_a[4], state_next[30], status[1], diag[14])
 *   rrr4_platform_design_apd_step(state[30], qa[4], xd[3], xd_dot[3], xd_ddot[3], params[23], design[2]) -> (tau_a[4], state_next[30], status[1], diag[14])
 *   rrr4_platform_design_apd_minmax_step(state[30], qa[4], xd[3], xd_dot[3], xd_ddot[3], params[23], design[2]) -> (tau_a[4], state_next[30], status[1], diag[14])
 *   rrr4_platform_design_apd_preload_step(state[30], qa[4], xd[3], xd_dot[3], xd_ddot[3], params[23], design[2]) -> (tau_a[4], state_next[30], status[1], diag[14])
 *   rrr4_platform_design_ctc_step(state[30], qa[4], xd[3], xd_dot[3], xd_ddot[3], params[23], design[2]) -> (tau_a[4], state_next[30], status[1], diag[14])
 *   rrr4_platform_design_ctc_minmax_step(state[30], qa[4], xd[3], xd_dot[3], xd_ddot[3], params[23], design[2]) -> (tau_a[4], state_next[30], status[1], diag[14])
 *   rrr4_platform_design_ctc_preload_step(state[30], qa[4], xd[3], xd_dot[3], xd_ddot[3], params[23], design[2]) -> (tau_a[4], state_next[30], status[1], diag[14])
 *   rrr4_platform_design_lqr_step(state[30], qa[4], xd[3], xd_dot[3], xd_ddot[3], params[17], K[24], tau_ff[4], design[2]) -> (tau_a[4], state_next[30], status[1], diag[14])
 *   rrr4_platform_design_lqr_minmax_step(state[30], qa[4], xd[3], xd_dot[3], xd_ddot[3], params[17], K[24], tau_ff[4], design[2]) -> (tau_a[4], state_next[30], status[1], diag[14])
 *   rrr4_platform_design_lqr_preload_step(state[30], qa[4], xd[3], xd_dot[3], xd_ddot[3], params[17], K[24], tau_ff[4], design[2]) -> (tau_a[4], state_next[30], status[1], diag[14])
 *   rrr4_platform_design_plant_xedd(xe[3], xed[3], tau_a[4], plant[31], design[2]) -> (xedd[3])
 *   rrr4_platform_design_plant_step(x[6], tau_a[4], plant[31], h[1], design[2]) -> (x_next[6])
 *   rrr4_platform_design_measure(xe[3], plant[31], design[2]) -> (qa[4])
 *   rrr4_platform_design_na_closed_loop(x[36], u[9], p[79], design[2]) -> (x_next[36], y[35])
 *   rrr4_platform_design_na_minmax_closed_loop(x[36], u[9], p[79], design[2]) -> (x_next[36], y[35])
 *   rrr4_platform_design_na_preload_closed_loop(x[36], u[9], p[79], design[2]) -> (x_next[36], y[35])
 *   rrr4_platform_design_na_proj_closed_loop(x[36], u[9], p[79], design[2]) -> (x_next[36], y[35])
 *   rrr4_platform_design_na_proj_minmax_closed_loop(x[36], u[9], p[79], design[2]) -> (x_next[36], y[35])
 *   rrr4_platform_design_na_proj_preload_closed_loop(x[36], u[9], p[79], design[2]) -> (x_next[36], y[35])
 *   rrr4_platform_design_apd_closed_loop(x[36], u[9], p[54], design[2]) -> (x_next[36], y[35])
 *   rrr4_platform_design_apd_minmax_closed_loop(x[36], u[9], p[54], design[2]) -> (x_next[36], y[35])
 *   rrr4_platform_design_apd_preload_closed_loop(x[36], u[9], p[54], design[2]) -> (x_next[36], y[35])
 *   rrr4_platform_design_ctc_closed_loop(x[36], u[9], p[54], design[2]) -> (x_next[36], y[35])
 *   rrr4_platform_design_ctc_minmax_closed_loop(x[36], u[9], p[54], design[2]) -> (x_next[36], y[35])
 *   rrr4_platform_design_ctc_preload_closed_loop(x[36], u[9], p[54], design[2]) -> (x_next[36], y[35])
 *   rrr4_platform_design_lqr_closed_loop(x[36], u[37], p[48], design[2]) -> (x_next[36], y[35])
 *   rrr4_platform_design_lqr_minmax_closed_loop(x[36], u[37], p[48], design[2]) -> (x_next[36], y[35])
 *   rrr4_platform_design_lqr_preload_closed_loop(x[36], u[37], p[48], design[2]) -> (x_next[36], y[35])
 *   rrr4_platform_design_path_coefficients(p[3], dp[3], ddp[3], theta[24], tau_max[4], design[2]) -> (a[3], b[3], S[12], v1[4], N_min_norm[18], h_min_norm[6], N_min_max[18], h_min_max[6], sing[2])
 *   rrr4_platform_design_path_mvc(stage[52], params[25]) -> (x_mvc[1])
 *   rrr4_platform_design_path_backward(x_next_max[1], input[108], params[25]) -> (x_max[1], y[1])
 *   rrr4_platform_design_path_forward(x[1], input[109], params[25]) -> (x_next[1], y[6])
 *   rrr4_platform_design_path_torques(stage[52], sd[1], sdd[1], params[25], tau_max[4]) -> (u[3], tau_min_norm[4], tau_min_max[4], min_max_ratio[1])
 *   rrr4_platform_design_forward_dynamics_jacobians(xe[3], xed[3], tau_a[4], theta[24], design[2]) -> (xedd[3], d_xe[9], d_xed[9], d_tau_a[12], d_theta[72], sing[2])
 *   rrr4_platform_design_inverse_dynamics(xe[3], xed[3], xedd[3], theta[24], design[2]) -> (u[3], sing[2])
 *   rrr4_platform_design_inverse_dynamics_jacobians(xe[3], xed[3], xedd[3], theta[24], design[2]) -> (u[3], d_xe[9], d_xed[9], sing[2])
 *   rrr4_platform_design_sampled_step(x[6], tau_a[4], theta[24], T[1], design[2]) -> (x_next[6], sing[2])
 *   rrr4_platform_design_sampled_step_jacobians(x[6], tau_a[4], theta[24], T[1], design[2]) -> (x_next[6], d_x[36], d_tau_a[24], sing[2])
 *   rrr4_platform_design_Ge(q[8], theta[24], design[2]) -> (Ge[3], sing[2])
 *   rrr4_platform_design_kinetic_energy(xe[3], xed[3], theta[24], design[2]) -> (T[1])
 *   rrr4_platform_design_potential_energy(xe[3], theta[24]) -> (V[1])
 *
 * Flat vectors of the controllers, plant and closed loop (field[count], in order):
 *   ctrl_state: xe_prev[3], v[3], theta_hat[24]
 *   na_params: Kd[3], Q[3], Gamma[24], freeze_saturated[1], T[1], vel_alpha[1], sing_threshold[1], parallel_sing_threshold[1], tau_max[4], preload_sign[4], preload[4], closure_tol[1]
 *   apd_params: Kp[3], Kv[3], T[1], vel_alpha[1], sing_threshold[1], parallel_sing_threshold[1], tau_max[4], preload_sign[4], preload[4], closure_tol[1]
 *   ctc_params: Kp[3], Kv[3], T[1], vel_alpha[1], sing_threshold[1], parallel_sing_threshold[1], tau_max[4], preload_sign[4], preload[4], closure_tol[1]
 *   lqr_params: T[1], vel_alpha[1], sing_threshold[1], parallel_sing_threshold[1], tau_max[4], preload_sign[4], preload[4], closure_tol[1]
 *   cl_state: xe[3], xed[3], ctrl_state[30]
 *   cl_input: xd[3], xd_dot[3], xd_ddot[3]
 *   cl_output: xe[3], xed[3], tau_a[4], status[1], theta_hat[24]
 *   lqr_cl_input: xd[3], xd_dot[3], xd_ddot[3], K[24], tau_ff[4]
 *   plant: alpha[4], beta[4], gamma[4], m_p[1], mx_p[1], my_p[1], I_p[1], fv[4], fc[4], fs[4], stribeck_velocity[1], coulomb_smoothing_velocity[1], encoder_step[1]
 *   path_stage: N[18], h[6], a[3], b[3], S[12], v1[4], rho[4], delta[1], x_cap[1]
 *   path_pair: stage[52], next[52], next_cap[1]
 *   path_backward_input: pair[105], same[1], x_in[1], x_out[1]
 *   path_forward_input: pair[105], x_next_max[1], same[1], x_in[1], x_out[1]
 *   path_forward_output: x[1], sdd[1], L[1], U[1], Z[1], arrival_ok[1]
 *   path_params: v_top[1], theta[24]
 *   status of a controller step: 0 ok, 1 singular, 2 saturated, 3 non_finite, 4 preload_infeasible, 5 inconsistent_encoders
 */
/* This file was automatically generated by CasADi 3.8.2.
 *  It consists of: 
 *   1) content generated by CasADi runtime: not copyrighted
 *   2) template code copied from CasADi source: permissively licensed (MIT-0)
 *   3) user code: owned by the user
 *
 */
#ifdef __cplusplus
extern "C" {
#endif

#ifndef casadi_real
#define casadi_real double
#endif

#ifndef casadi_int
#define casadi_int long long int
#endif

int rrr4_platform_design_ik(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_ik_checkout(void);
void rrr4_platform_design_ik_release(int mem);
void rrr4_platform_design_ik_incref(void);
void rrr4_platform_design_ik_decref(void);
casadi_int rrr4_platform_design_ik_n_in(void);
casadi_int rrr4_platform_design_ik_n_out(void);
casadi_real rrr4_platform_design_ik_default_in(casadi_int i);
const char* rrr4_platform_design_ik_name_in(casadi_int i);
const char* rrr4_platform_design_ik_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_ik_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_ik_sparsity_out(casadi_int i);
int rrr4_platform_design_ik_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_ik_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_ik_SZ_ARG 2
#define rrr4_platform_design_ik_SZ_RES 1
#define rrr4_platform_design_ik_SZ_IW 0
#define rrr4_platform_design_ik_SZ_W 0
int rrr4_platform_design_fk(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_fk_checkout(void);
void rrr4_platform_design_fk_release(int mem);
void rrr4_platform_design_fk_incref(void);
void rrr4_platform_design_fk_decref(void);
casadi_int rrr4_platform_design_fk_n_in(void);
casadi_int rrr4_platform_design_fk_n_out(void);
casadi_real rrr4_platform_design_fk_default_in(casadi_int i);
const char* rrr4_platform_design_fk_name_in(casadi_int i);
const char* rrr4_platform_design_fk_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_fk_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_fk_sparsity_out(casadi_int i);
int rrr4_platform_design_fk_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_fk_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_fk_SZ_ARG 2
#define rrr4_platform_design_fk_SZ_RES 2
#define rrr4_platform_design_fk_SZ_IW 0
#define rrr4_platform_design_fk_SZ_W 0
int rrr4_platform_design_H(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_H_checkout(void);
void rrr4_platform_design_H_release(int mem);
void rrr4_platform_design_H_incref(void);
void rrr4_platform_design_H_decref(void);
casadi_int rrr4_platform_design_H_n_in(void);
casadi_int rrr4_platform_design_H_n_out(void);
casadi_real rrr4_platform_design_H_default_in(casadi_int i);
const char* rrr4_platform_design_H_name_in(casadi_int i);
const char* rrr4_platform_design_H_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_H_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_H_sparsity_out(casadi_int i);
int rrr4_platform_design_H_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_H_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_H_SZ_ARG 2
#define rrr4_platform_design_H_SZ_RES 1
#define rrr4_platform_design_H_SZ_IW 0
#define rrr4_platform_design_H_SZ_W 0
int rrr4_platform_design_A(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_A_checkout(void);
void rrr4_platform_design_A_release(int mem);
void rrr4_platform_design_A_incref(void);
void rrr4_platform_design_A_decref(void);
casadi_int rrr4_platform_design_A_n_in(void);
casadi_int rrr4_platform_design_A_n_out(void);
casadi_real rrr4_platform_design_A_default_in(casadi_int i);
const char* rrr4_platform_design_A_name_in(casadi_int i);
const char* rrr4_platform_design_A_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_A_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_A_sparsity_out(casadi_int i);
int rrr4_platform_design_A_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_A_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_A_SZ_ARG 2
#define rrr4_platform_design_A_SZ_RES 1
#define rrr4_platform_design_A_SZ_IW 0
#define rrr4_platform_design_A_SZ_W 0
int rrr4_platform_design_singularity(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_singularity_checkout(void);
void rrr4_platform_design_singularity_release(int mem);
void rrr4_platform_design_singularity_incref(void);
void rrr4_platform_design_singularity_decref(void);
casadi_int rrr4_platform_design_singularity_n_in(void);
casadi_int rrr4_platform_design_singularity_n_out(void);
casadi_real rrr4_platform_design_singularity_default_in(casadi_int i);
const char* rrr4_platform_design_singularity_name_in(casadi_int i);
const char* rrr4_platform_design_singularity_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_singularity_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_singularity_sparsity_out(casadi_int i);
int rrr4_platform_design_singularity_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_singularity_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_singularity_SZ_ARG 1
#define rrr4_platform_design_singularity_SZ_RES 1
#define rrr4_platform_design_singularity_SZ_IW 0
#define rrr4_platform_design_singularity_SZ_W 0
int rrr4_platform_design_singularity_measures(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_singularity_measures_checkout(void);
void rrr4_platform_design_singularity_measures_release(int mem);
void rrr4_platform_design_singularity_measures_incref(void);
void rrr4_platform_design_singularity_measures_decref(void);
casadi_int rrr4_platform_design_singularity_measures_n_in(void);
casadi_int rrr4_platform_design_singularity_measures_n_out(void);
casadi_real rrr4_platform_design_singularity_measures_default_in(casadi_int i);
const char* rrr4_platform_design_singularity_measures_name_in(casadi_int i);
const char* rrr4_platform_design_singularity_measures_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_singularity_measures_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_singularity_measures_sparsity_out(casadi_int i);
int rrr4_platform_design_singularity_measures_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_singularity_measures_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_singularity_measures_SZ_ARG 2
#define rrr4_platform_design_singularity_measures_SZ_RES 1
#define rrr4_platform_design_singularity_measures_SZ_IW 0
#define rrr4_platform_design_singularity_measures_SZ_W 0
int rrr4_platform_design_W(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_W_checkout(void);
void rrr4_platform_design_W_release(int mem);
void rrr4_platform_design_W_incref(void);
void rrr4_platform_design_W_decref(void);
casadi_int rrr4_platform_design_W_n_in(void);
casadi_int rrr4_platform_design_W_n_out(void);
casadi_real rrr4_platform_design_W_default_in(casadi_int i);
const char* rrr4_platform_design_W_name_in(casadi_int i);
const char* rrr4_platform_design_W_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_W_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_W_sparsity_out(casadi_int i);
int rrr4_platform_design_W_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_W_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_W_SZ_ARG 2
#define rrr4_platform_design_W_SZ_RES 2
#define rrr4_platform_design_W_SZ_IW 0
#define rrr4_platform_design_W_SZ_W 0
int rrr4_platform_design_S(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_S_checkout(void);
void rrr4_platform_design_S_release(int mem);
void rrr4_platform_design_S_incref(void);
void rrr4_platform_design_S_decref(void);
casadi_int rrr4_platform_design_S_n_in(void);
casadi_int rrr4_platform_design_S_n_out(void);
casadi_real rrr4_platform_design_S_default_in(casadi_int i);
const char* rrr4_platform_design_S_name_in(casadi_int i);
const char* rrr4_platform_design_S_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_S_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_S_sparsity_out(casadi_int i);
int rrr4_platform_design_S_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_S_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_S_SZ_ARG 2
#define rrr4_platform_design_S_SZ_RES 2
#define rrr4_platform_design_S_SZ_IW 0
#define rrr4_platform_design_S_SZ_W 0
int rrr4_platform_design_Wdot(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_Wdot_checkout(void);
void rrr4_platform_design_Wdot_release(int mem);
void rrr4_platform_design_Wdot_incref(void);
void rrr4_platform_design_Wdot_decref(void);
casadi_int rrr4_platform_design_Wdot_n_in(void);
casadi_int rrr4_platform_design_Wdot_n_out(void);
casadi_real rrr4_platform_design_Wdot_default_in(casadi_int i);
const char* rrr4_platform_design_Wdot_name_in(casadi_int i);
const char* rrr4_platform_design_Wdot_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_Wdot_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_Wdot_sparsity_out(casadi_int i);
int rrr4_platform_design_Wdot_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_Wdot_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_Wdot_SZ_ARG 3
#define rrr4_platform_design_Wdot_SZ_RES 2
#define rrr4_platform_design_Wdot_SZ_IW 0
#define rrr4_platform_design_Wdot_SZ_W 0
int rrr4_platform_design_M(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_M_checkout(void);
void rrr4_platform_design_M_release(int mem);
void rrr4_platform_design_M_incref(void);
void rrr4_platform_design_M_decref(void);
casadi_int rrr4_platform_design_M_n_in(void);
casadi_int rrr4_platform_design_M_n_out(void);
casadi_real rrr4_platform_design_M_default_in(casadi_int i);
const char* rrr4_platform_design_M_name_in(casadi_int i);
const char* rrr4_platform_design_M_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_M_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_M_sparsity_out(casadi_int i);
int rrr4_platform_design_M_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_M_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_M_SZ_ARG 2
#define rrr4_platform_design_M_SZ_RES 1
#define rrr4_platform_design_M_SZ_IW 0
#define rrr4_platform_design_M_SZ_W 0
int rrr4_platform_design_C(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_C_checkout(void);
void rrr4_platform_design_C_release(int mem);
void rrr4_platform_design_C_incref(void);
void rrr4_platform_design_C_decref(void);
casadi_int rrr4_platform_design_C_n_in(void);
casadi_int rrr4_platform_design_C_n_out(void);
casadi_real rrr4_platform_design_C_default_in(casadi_int i);
const char* rrr4_platform_design_C_name_in(casadi_int i);
const char* rrr4_platform_design_C_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_C_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_C_sparsity_out(casadi_int i);
int rrr4_platform_design_C_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_C_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_C_SZ_ARG 3
#define rrr4_platform_design_C_SZ_RES 1
#define rrr4_platform_design_C_SZ_IW 0
#define rrr4_platform_design_C_SZ_W 0
int rrr4_platform_design_Me(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_Me_checkout(void);
void rrr4_platform_design_Me_release(int mem);
void rrr4_platform_design_Me_incref(void);
void rrr4_platform_design_Me_decref(void);
casadi_int rrr4_platform_design_Me_n_in(void);
casadi_int rrr4_platform_design_Me_n_out(void);
casadi_real rrr4_platform_design_Me_default_in(casadi_int i);
const char* rrr4_platform_design_Me_name_in(casadi_int i);
const char* rrr4_platform_design_Me_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_Me_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_Me_sparsity_out(casadi_int i);
int rrr4_platform_design_Me_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_Me_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_Me_SZ_ARG 3
#define rrr4_platform_design_Me_SZ_RES 2
#define rrr4_platform_design_Me_SZ_IW 0
#define rrr4_platform_design_Me_SZ_W 0
int rrr4_platform_design_Ce(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_Ce_checkout(void);
void rrr4_platform_design_Ce_release(int mem);
void rrr4_platform_design_Ce_incref(void);
void rrr4_platform_design_Ce_decref(void);
casadi_int rrr4_platform_design_Ce_n_in(void);
casadi_int rrr4_platform_design_Ce_n_out(void);
casadi_real rrr4_platform_design_Ce_default_in(casadi_int i);
const char* rrr4_platform_design_Ce_name_in(casadi_int i);
const char* rrr4_platform_design_Ce_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_Ce_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_Ce_sparsity_out(casadi_int i);
int rrr4_platform_design_Ce_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_Ce_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_Ce_SZ_ARG 4
#define rrr4_platform_design_Ce_SZ_RES 2
#define rrr4_platform_design_Ce_SZ_IW 0
#define rrr4_platform_design_Ce_SZ_W 0
int rrr4_platform_design_StF(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_StF_checkout(void);
void rrr4_platform_design_StF_release(int mem);
void rrr4_platform_design_StF_incref(void);
void rrr4_platform_design_StF_decref(void);
casadi_int rrr4_platform_design_StF_n_in(void);
casadi_int rrr4_platform_design_StF_n_out(void);
casadi_real rrr4_platform_design_StF_default_in(casadi_int i);
const char* rrr4_platform_design_StF_name_in(casadi_int i);
const char* rrr4_platform_design_StF_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_StF_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_StF_sparsity_out(casadi_int i);
int rrr4_platform_design_StF_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_StF_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_StF_SZ_ARG 4
#define rrr4_platform_design_StF_SZ_RES 2
#define rrr4_platform_design_StF_SZ_IW 0
#define rrr4_platform_design_StF_SZ_W 0
int rrr4_platform_design_Y(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_Y_checkout(void);
void rrr4_platform_design_Y_release(int mem);
void rrr4_platform_design_Y_incref(void);
void rrr4_platform_design_Y_decref(void);
casadi_int rrr4_platform_design_Y_n_in(void);
casadi_int rrr4_platform_design_Y_n_out(void);
casadi_real rrr4_platform_design_Y_default_in(casadi_int i);
const char* rrr4_platform_design_Y_name_in(casadi_int i);
const char* rrr4_platform_design_Y_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_Y_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_Y_sparsity_out(casadi_int i);
int rrr4_platform_design_Y_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_Y_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_Y_SZ_ARG 5
#define rrr4_platform_design_Y_SZ_RES 2
#define rrr4_platform_design_Y_SZ_IW 0
#define rrr4_platform_design_Y_SZ_W 0
int rrr4_platform_design_torque_splits(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_torque_splits_checkout(void);
void rrr4_platform_design_torque_splits_release(int mem);
void rrr4_platform_design_torque_splits_incref(void);
void rrr4_platform_design_torque_splits_decref(void);
casadi_int rrr4_platform_design_torque_splits_n_in(void);
casadi_int rrr4_platform_design_torque_splits_n_out(void);
casadi_real rrr4_platform_design_torque_splits_default_in(casadi_int i);
const char* rrr4_platform_design_torque_splits_name_in(casadi_int i);
const char* rrr4_platform_design_torque_splits_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_torque_splits_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_torque_splits_sparsity_out(casadi_int i);
int rrr4_platform_design_torque_splits_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_torque_splits_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_torque_splits_SZ_ARG 11
#define rrr4_platform_design_torque_splits_SZ_RES 8
#define rrr4_platform_design_torque_splits_SZ_IW 0
#define rrr4_platform_design_torque_splits_SZ_W 328
int rrr4_platform_design_forward_dynamics(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_forward_dynamics_checkout(void);
void rrr4_platform_design_forward_dynamics_release(int mem);
void rrr4_platform_design_forward_dynamics_incref(void);
void rrr4_platform_design_forward_dynamics_decref(void);
casadi_int rrr4_platform_design_forward_dynamics_n_in(void);
casadi_int rrr4_platform_design_forward_dynamics_n_out(void);
casadi_real rrr4_platform_design_forward_dynamics_default_in(casadi_int i);
const char* rrr4_platform_design_forward_dynamics_name_in(casadi_int i);
const char* rrr4_platform_design_forward_dynamics_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_forward_dynamics_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_forward_dynamics_sparsity_out(casadi_int i);
int rrr4_platform_design_forward_dynamics_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_forward_dynamics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_forward_dynamics_SZ_ARG 5
#define rrr4_platform_design_forward_dynamics_SZ_RES 2
#define rrr4_platform_design_forward_dynamics_SZ_IW 0
#define rrr4_platform_design_forward_dynamics_SZ_W 0
int rrr4_platform_design_na_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_na_step_checkout(void);
void rrr4_platform_design_na_step_release(int mem);
void rrr4_platform_design_na_step_incref(void);
void rrr4_platform_design_na_step_decref(void);
casadi_int rrr4_platform_design_na_step_n_in(void);
casadi_int rrr4_platform_design_na_step_n_out(void);
casadi_real rrr4_platform_design_na_step_default_in(casadi_int i);
const char* rrr4_platform_design_na_step_name_in(casadi_int i);
const char* rrr4_platform_design_na_step_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_na_step_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_na_step_sparsity_out(casadi_int i);
int rrr4_platform_design_na_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_na_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_na_step_SZ_ARG 7
#define rrr4_platform_design_na_step_SZ_RES 4
#define rrr4_platform_design_na_step_SZ_IW 0
#define rrr4_platform_design_na_step_SZ_W 0
int rrr4_platform_design_na_minmax_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_na_minmax_step_checkout(void);
void rrr4_platform_design_na_minmax_step_release(int mem);
void rrr4_platform_design_na_minmax_step_incref(void);
void rrr4_platform_design_na_minmax_step_decref(void);
casadi_int rrr4_platform_design_na_minmax_step_n_in(void);
casadi_int rrr4_platform_design_na_minmax_step_n_out(void);
casadi_real rrr4_platform_design_na_minmax_step_default_in(casadi_int i);
const char* rrr4_platform_design_na_minmax_step_name_in(casadi_int i);
const char* rrr4_platform_design_na_minmax_step_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_na_minmax_step_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_na_minmax_step_sparsity_out(casadi_int i);
int rrr4_platform_design_na_minmax_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_na_minmax_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_na_minmax_step_SZ_ARG 7
#define rrr4_platform_design_na_minmax_step_SZ_RES 4
#define rrr4_platform_design_na_minmax_step_SZ_IW 0
#define rrr4_platform_design_na_minmax_step_SZ_W 0
int rrr4_platform_design_na_preload_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_na_preload_step_checkout(void);
void rrr4_platform_design_na_preload_step_release(int mem);
void rrr4_platform_design_na_preload_step_incref(void);
void rrr4_platform_design_na_preload_step_decref(void);
casadi_int rrr4_platform_design_na_preload_step_n_in(void);
casadi_int rrr4_platform_design_na_preload_step_n_out(void);
casadi_real rrr4_platform_design_na_preload_step_default_in(casadi_int i);
const char* rrr4_platform_design_na_preload_step_name_in(casadi_int i);
const char* rrr4_platform_design_na_preload_step_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_na_preload_step_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_na_preload_step_sparsity_out(casadi_int i);
int rrr4_platform_design_na_preload_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_na_preload_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_na_preload_step_SZ_ARG 12
#define rrr4_platform_design_na_preload_step_SZ_RES 6
#define rrr4_platform_design_na_preload_step_SZ_IW 0
#define rrr4_platform_design_na_preload_step_SZ_W 328
int rrr4_platform_design_na_proj_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_na_proj_step_checkout(void);
void rrr4_platform_design_na_proj_step_release(int mem);
void rrr4_platform_design_na_proj_step_incref(void);
void rrr4_platform_design_na_proj_step_decref(void);
casadi_int rrr4_platform_design_na_proj_step_n_in(void);
casadi_int rrr4_platform_design_na_proj_step_n_out(void);
casadi_real rrr4_platform_design_na_proj_step_default_in(casadi_int i);
const char* rrr4_platform_design_na_proj_step_name_in(casadi_int i);
const char* rrr4_platform_design_na_proj_step_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_na_proj_step_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_na_proj_step_sparsity_out(casadi_int i);
int rrr4_platform_design_na_proj_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_na_proj_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_na_proj_step_SZ_ARG 7
#define rrr4_platform_design_na_proj_step_SZ_RES 4
#define rrr4_platform_design_na_proj_step_SZ_IW 0
#define rrr4_platform_design_na_proj_step_SZ_W 0
int rrr4_platform_design_na_proj_minmax_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_na_proj_minmax_step_checkout(void);
void rrr4_platform_design_na_proj_minmax_step_release(int mem);
void rrr4_platform_design_na_proj_minmax_step_incref(void);
void rrr4_platform_design_na_proj_minmax_step_decref(void);
casadi_int rrr4_platform_design_na_proj_minmax_step_n_in(void);
casadi_int rrr4_platform_design_na_proj_minmax_step_n_out(void);
casadi_real rrr4_platform_design_na_proj_minmax_step_default_in(casadi_int i);
const char* rrr4_platform_design_na_proj_minmax_step_name_in(casadi_int i);
const char* rrr4_platform_design_na_proj_minmax_step_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_na_proj_minmax_step_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_na_proj_minmax_step_sparsity_out(casadi_int i);
int rrr4_platform_design_na_proj_minmax_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_na_proj_minmax_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_na_proj_minmax_step_SZ_ARG 7
#define rrr4_platform_design_na_proj_minmax_step_SZ_RES 4
#define rrr4_platform_design_na_proj_minmax_step_SZ_IW 0
#define rrr4_platform_design_na_proj_minmax_step_SZ_W 0
int rrr4_platform_design_na_proj_preload_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_na_proj_preload_step_checkout(void);
void rrr4_platform_design_na_proj_preload_step_release(int mem);
void rrr4_platform_design_na_proj_preload_step_incref(void);
void rrr4_platform_design_na_proj_preload_step_decref(void);
casadi_int rrr4_platform_design_na_proj_preload_step_n_in(void);
casadi_int rrr4_platform_design_na_proj_preload_step_n_out(void);
casadi_real rrr4_platform_design_na_proj_preload_step_default_in(casadi_int i);
const char* rrr4_platform_design_na_proj_preload_step_name_in(casadi_int i);
const char* rrr4_platform_design_na_proj_preload_step_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_na_proj_preload_step_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_na_proj_preload_step_sparsity_out(casadi_int i);
int rrr4_platform_design_na_proj_preload_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_na_proj_preload_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_na_proj_preload_step_SZ_ARG 12
#define rrr4_platform_design_na_proj_preload_step_SZ_RES 6
#define rrr4_platform_design_na_proj_preload_step_SZ_IW 0
#define rrr4_platform_design_na_proj_preload_step_SZ_W 328
int rrr4_platform_design_apd_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_apd_step_checkout(void);
void rrr4_platform_design_apd_step_release(int mem);
void rrr4_platform_design_apd_step_incref(void);
void rrr4_platform_design_apd_step_decref(void);
casadi_int rrr4_platform_design_apd_step_n_in(void);
casadi_int rrr4_platform_design_apd_step_n_out(void);
casadi_real rrr4_platform_design_apd_step_default_in(casadi_int i);
const char* rrr4_platform_design_apd_step_name_in(casadi_int i);
const char* rrr4_platform_design_apd_step_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_apd_step_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_apd_step_sparsity_out(casadi_int i);
int rrr4_platform_design_apd_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_apd_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_apd_step_SZ_ARG 7
#define rrr4_platform_design_apd_step_SZ_RES 4
#define rrr4_platform_design_apd_step_SZ_IW 0
#define rrr4_platform_design_apd_step_SZ_W 0
int rrr4_platform_design_apd_minmax_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_apd_minmax_step_checkout(void);
void rrr4_platform_design_apd_minmax_step_release(int mem);
void rrr4_platform_design_apd_minmax_step_incref(void);
void rrr4_platform_design_apd_minmax_step_decref(void);
casadi_int rrr4_platform_design_apd_minmax_step_n_in(void);
casadi_int rrr4_platform_design_apd_minmax_step_n_out(void);
casadi_real rrr4_platform_design_apd_minmax_step_default_in(casadi_int i);
const char* rrr4_platform_design_apd_minmax_step_name_in(casadi_int i);
const char* rrr4_platform_design_apd_minmax_step_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_apd_minmax_step_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_apd_minmax_step_sparsity_out(casadi_int i);
int rrr4_platform_design_apd_minmax_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_apd_minmax_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_apd_minmax_step_SZ_ARG 7
#define rrr4_platform_design_apd_minmax_step_SZ_RES 4
#define rrr4_platform_design_apd_minmax_step_SZ_IW 0
#define rrr4_platform_design_apd_minmax_step_SZ_W 0
int rrr4_platform_design_apd_preload_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_apd_preload_step_checkout(void);
void rrr4_platform_design_apd_preload_step_release(int mem);
void rrr4_platform_design_apd_preload_step_incref(void);
void rrr4_platform_design_apd_preload_step_decref(void);
casadi_int rrr4_platform_design_apd_preload_step_n_in(void);
casadi_int rrr4_platform_design_apd_preload_step_n_out(void);
casadi_real rrr4_platform_design_apd_preload_step_default_in(casadi_int i);
const char* rrr4_platform_design_apd_preload_step_name_in(casadi_int i);
const char* rrr4_platform_design_apd_preload_step_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_apd_preload_step_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_apd_preload_step_sparsity_out(casadi_int i);
int rrr4_platform_design_apd_preload_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_apd_preload_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_apd_preload_step_SZ_ARG 12
#define rrr4_platform_design_apd_preload_step_SZ_RES 6
#define rrr4_platform_design_apd_preload_step_SZ_IW 0
#define rrr4_platform_design_apd_preload_step_SZ_W 328
int rrr4_platform_design_ctc_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_ctc_step_checkout(void);
void rrr4_platform_design_ctc_step_release(int mem);
void rrr4_platform_design_ctc_step_incref(void);
void rrr4_platform_design_ctc_step_decref(void);
casadi_int rrr4_platform_design_ctc_step_n_in(void);
casadi_int rrr4_platform_design_ctc_step_n_out(void);
casadi_real rrr4_platform_design_ctc_step_default_in(casadi_int i);
const char* rrr4_platform_design_ctc_step_name_in(casadi_int i);
const char* rrr4_platform_design_ctc_step_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_ctc_step_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_ctc_step_sparsity_out(casadi_int i);
int rrr4_platform_design_ctc_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_ctc_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_ctc_step_SZ_ARG 7
#define rrr4_platform_design_ctc_step_SZ_RES 4
#define rrr4_platform_design_ctc_step_SZ_IW 0
#define rrr4_platform_design_ctc_step_SZ_W 0
int rrr4_platform_design_ctc_minmax_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_ctc_minmax_step_checkout(void);
void rrr4_platform_design_ctc_minmax_step_release(int mem);
void rrr4_platform_design_ctc_minmax_step_incref(void);
void rrr4_platform_design_ctc_minmax_step_decref(void);
casadi_int rrr4_platform_design_ctc_minmax_step_n_in(void);
casadi_int rrr4_platform_design_ctc_minmax_step_n_out(void);
casadi_real rrr4_platform_design_ctc_minmax_step_default_in(casadi_int i);
const char* rrr4_platform_design_ctc_minmax_step_name_in(casadi_int i);
const char* rrr4_platform_design_ctc_minmax_step_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_ctc_minmax_step_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_ctc_minmax_step_sparsity_out(casadi_int i);
int rrr4_platform_design_ctc_minmax_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_ctc_minmax_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_ctc_minmax_step_SZ_ARG 7
#define rrr4_platform_design_ctc_minmax_step_SZ_RES 4
#define rrr4_platform_design_ctc_minmax_step_SZ_IW 0
#define rrr4_platform_design_ctc_minmax_step_SZ_W 0
int rrr4_platform_design_ctc_preload_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_ctc_preload_step_checkout(void);
void rrr4_platform_design_ctc_preload_step_release(int mem);
void rrr4_platform_design_ctc_preload_step_incref(void);
void rrr4_platform_design_ctc_preload_step_decref(void);
casadi_int rrr4_platform_design_ctc_preload_step_n_in(void);
casadi_int rrr4_platform_design_ctc_preload_step_n_out(void);
casadi_real rrr4_platform_design_ctc_preload_step_default_in(casadi_int i);
const char* rrr4_platform_design_ctc_preload_step_name_in(casadi_int i);
const char* rrr4_platform_design_ctc_preload_step_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_ctc_preload_step_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_ctc_preload_step_sparsity_out(casadi_int i);
int rrr4_platform_design_ctc_preload_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_ctc_preload_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_ctc_preload_step_SZ_ARG 12
#define rrr4_platform_design_ctc_preload_step_SZ_RES 6
#define rrr4_platform_design_ctc_preload_step_SZ_IW 0
#define rrr4_platform_design_ctc_preload_step_SZ_W 328
int rrr4_platform_design_lqr_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_lqr_step_checkout(void);
void rrr4_platform_design_lqr_step_release(int mem);
void rrr4_platform_design_lqr_step_incref(void);
void rrr4_platform_design_lqr_step_decref(void);
casadi_int rrr4_platform_design_lqr_step_n_in(void);
casadi_int rrr4_platform_design_lqr_step_n_out(void);
casadi_real rrr4_platform_design_lqr_step_default_in(casadi_int i);
const char* rrr4_platform_design_lqr_step_name_in(casadi_int i);
const char* rrr4_platform_design_lqr_step_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_lqr_step_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_lqr_step_sparsity_out(casadi_int i);
int rrr4_platform_design_lqr_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_lqr_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_lqr_step_SZ_ARG 9
#define rrr4_platform_design_lqr_step_SZ_RES 4
#define rrr4_platform_design_lqr_step_SZ_IW 0
#define rrr4_platform_design_lqr_step_SZ_W 0
int rrr4_platform_design_lqr_minmax_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_lqr_minmax_step_checkout(void);
void rrr4_platform_design_lqr_minmax_step_release(int mem);
void rrr4_platform_design_lqr_minmax_step_incref(void);
void rrr4_platform_design_lqr_minmax_step_decref(void);
casadi_int rrr4_platform_design_lqr_minmax_step_n_in(void);
casadi_int rrr4_platform_design_lqr_minmax_step_n_out(void);
casadi_real rrr4_platform_design_lqr_minmax_step_default_in(casadi_int i);
const char* rrr4_platform_design_lqr_minmax_step_name_in(casadi_int i);
const char* rrr4_platform_design_lqr_minmax_step_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_lqr_minmax_step_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_lqr_minmax_step_sparsity_out(casadi_int i);
int rrr4_platform_design_lqr_minmax_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_lqr_minmax_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_lqr_minmax_step_SZ_ARG 9
#define rrr4_platform_design_lqr_minmax_step_SZ_RES 4
#define rrr4_platform_design_lqr_minmax_step_SZ_IW 0
#define rrr4_platform_design_lqr_minmax_step_SZ_W 0
int rrr4_platform_design_lqr_preload_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_lqr_preload_step_checkout(void);
void rrr4_platform_design_lqr_preload_step_release(int mem);
void rrr4_platform_design_lqr_preload_step_incref(void);
void rrr4_platform_design_lqr_preload_step_decref(void);
casadi_int rrr4_platform_design_lqr_preload_step_n_in(void);
casadi_int rrr4_platform_design_lqr_preload_step_n_out(void);
casadi_real rrr4_platform_design_lqr_preload_step_default_in(casadi_int i);
const char* rrr4_platform_design_lqr_preload_step_name_in(casadi_int i);
const char* rrr4_platform_design_lqr_preload_step_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_lqr_preload_step_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_lqr_preload_step_sparsity_out(casadi_int i);
int rrr4_platform_design_lqr_preload_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_lqr_preload_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_lqr_preload_step_SZ_ARG 14
#define rrr4_platform_design_lqr_preload_step_SZ_RES 6
#define rrr4_platform_design_lqr_preload_step_SZ_IW 0
#define rrr4_platform_design_lqr_preload_step_SZ_W 328
int rrr4_platform_design_plant_xedd(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_plant_xedd_checkout(void);
void rrr4_platform_design_plant_xedd_release(int mem);
void rrr4_platform_design_plant_xedd_incref(void);
void rrr4_platform_design_plant_xedd_decref(void);
casadi_int rrr4_platform_design_plant_xedd_n_in(void);
casadi_int rrr4_platform_design_plant_xedd_n_out(void);
casadi_real rrr4_platform_design_plant_xedd_default_in(casadi_int i);
const char* rrr4_platform_design_plant_xedd_name_in(casadi_int i);
const char* rrr4_platform_design_plant_xedd_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_plant_xedd_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_plant_xedd_sparsity_out(casadi_int i);
int rrr4_platform_design_plant_xedd_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_plant_xedd_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_plant_xedd_SZ_ARG 5
#define rrr4_platform_design_plant_xedd_SZ_RES 1
#define rrr4_platform_design_plant_xedd_SZ_IW 0
#define rrr4_platform_design_plant_xedd_SZ_W 0
int rrr4_platform_design_plant_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_plant_step_checkout(void);
void rrr4_platform_design_plant_step_release(int mem);
void rrr4_platform_design_plant_step_incref(void);
void rrr4_platform_design_plant_step_decref(void);
casadi_int rrr4_platform_design_plant_step_n_in(void);
casadi_int rrr4_platform_design_plant_step_n_out(void);
casadi_real rrr4_platform_design_plant_step_default_in(casadi_int i);
const char* rrr4_platform_design_plant_step_name_in(casadi_int i);
const char* rrr4_platform_design_plant_step_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_plant_step_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_plant_step_sparsity_out(casadi_int i);
int rrr4_platform_design_plant_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_plant_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_plant_step_SZ_ARG 5
#define rrr4_platform_design_plant_step_SZ_RES 1
#define rrr4_platform_design_plant_step_SZ_IW 0
#define rrr4_platform_design_plant_step_SZ_W 0
int rrr4_platform_design_measure(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_measure_checkout(void);
void rrr4_platform_design_measure_release(int mem);
void rrr4_platform_design_measure_incref(void);
void rrr4_platform_design_measure_decref(void);
casadi_int rrr4_platform_design_measure_n_in(void);
casadi_int rrr4_platform_design_measure_n_out(void);
casadi_real rrr4_platform_design_measure_default_in(casadi_int i);
const char* rrr4_platform_design_measure_name_in(casadi_int i);
const char* rrr4_platform_design_measure_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_measure_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_measure_sparsity_out(casadi_int i);
int rrr4_platform_design_measure_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_measure_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_measure_SZ_ARG 3
#define rrr4_platform_design_measure_SZ_RES 1
#define rrr4_platform_design_measure_SZ_IW 0
#define rrr4_platform_design_measure_SZ_W 0
int rrr4_platform_design_na_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_na_closed_loop_checkout(void);
void rrr4_platform_design_na_closed_loop_release(int mem);
void rrr4_platform_design_na_closed_loop_incref(void);
void rrr4_platform_design_na_closed_loop_decref(void);
casadi_int rrr4_platform_design_na_closed_loop_n_in(void);
casadi_int rrr4_platform_design_na_closed_loop_n_out(void);
casadi_real rrr4_platform_design_na_closed_loop_default_in(casadi_int i);
const char* rrr4_platform_design_na_closed_loop_name_in(casadi_int i);
const char* rrr4_platform_design_na_closed_loop_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_na_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_na_closed_loop_sparsity_out(casadi_int i);
int rrr4_platform_design_na_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_na_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_na_closed_loop_SZ_ARG 11
#define rrr4_platform_design_na_closed_loop_SZ_RES 6
#define rrr4_platform_design_na_closed_loop_SZ_IW 0
#define rrr4_platform_design_na_closed_loop_SZ_W 231
int rrr4_platform_design_na_minmax_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_na_minmax_closed_loop_checkout(void);
void rrr4_platform_design_na_minmax_closed_loop_release(int mem);
void rrr4_platform_design_na_minmax_closed_loop_incref(void);
void rrr4_platform_design_na_minmax_closed_loop_decref(void);
casadi_int rrr4_platform_design_na_minmax_closed_loop_n_in(void);
casadi_int rrr4_platform_design_na_minmax_closed_loop_n_out(void);
casadi_real rrr4_platform_design_na_minmax_closed_loop_default_in(casadi_int i);
const char* rrr4_platform_design_na_minmax_closed_loop_name_in(casadi_int i);
const char* rrr4_platform_design_na_minmax_closed_loop_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_na_minmax_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_na_minmax_closed_loop_sparsity_out(casadi_int i);
int rrr4_platform_design_na_minmax_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_na_minmax_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_na_minmax_closed_loop_SZ_ARG 11
#define rrr4_platform_design_na_minmax_closed_loop_SZ_RES 6
#define rrr4_platform_design_na_minmax_closed_loop_SZ_IW 0
#define rrr4_platform_design_na_minmax_closed_loop_SZ_W 258
int rrr4_platform_design_na_preload_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_na_preload_closed_loop_checkout(void);
void rrr4_platform_design_na_preload_closed_loop_release(int mem);
void rrr4_platform_design_na_preload_closed_loop_incref(void);
void rrr4_platform_design_na_preload_closed_loop_decref(void);
casadi_int rrr4_platform_design_na_preload_closed_loop_n_in(void);
casadi_int rrr4_platform_design_na_preload_closed_loop_n_out(void);
casadi_real rrr4_platform_design_na_preload_closed_loop_default_in(casadi_int i);
const char* rrr4_platform_design_na_preload_closed_loop_name_in(casadi_int i);
const char* rrr4_platform_design_na_preload_closed_loop_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_na_preload_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_na_preload_closed_loop_sparsity_out(casadi_int i);
int rrr4_platform_design_na_preload_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_na_preload_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_na_preload_closed_loop_SZ_ARG 16
#define rrr4_platform_design_na_preload_closed_loop_SZ_RES 8
#define rrr4_platform_design_na_preload_closed_loop_SZ_IW 0
#define rrr4_platform_design_na_preload_closed_loop_SZ_W 553
int rrr4_platform_design_na_proj_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_na_proj_closed_loop_checkout(void);
void rrr4_platform_design_na_proj_closed_loop_release(int mem);
void rrr4_platform_design_na_proj_closed_loop_incref(void);
void rrr4_platform_design_na_proj_closed_loop_decref(void);
casadi_int rrr4_platform_design_na_proj_closed_loop_n_in(void);
casadi_int rrr4_platform_design_na_proj_closed_loop_n_out(void);
casadi_real rrr4_platform_design_na_proj_closed_loop_default_in(casadi_int i);
const char* rrr4_platform_design_na_proj_closed_loop_name_in(casadi_int i);
const char* rrr4_platform_design_na_proj_closed_loop_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_na_proj_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_na_proj_closed_loop_sparsity_out(casadi_int i);
int rrr4_platform_design_na_proj_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_na_proj_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_na_proj_closed_loop_SZ_ARG 11
#define rrr4_platform_design_na_proj_closed_loop_SZ_RES 6
#define rrr4_platform_design_na_proj_closed_loop_SZ_IW 0
#define rrr4_platform_design_na_proj_closed_loop_SZ_W 231
int rrr4_platform_design_na_proj_minmax_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_na_proj_minmax_closed_loop_checkout(void);
void rrr4_platform_design_na_proj_minmax_closed_loop_release(int mem);
void rrr4_platform_design_na_proj_minmax_closed_loop_incref(void);
void rrr4_platform_design_na_proj_minmax_closed_loop_decref(void);
casadi_int rrr4_platform_design_na_proj_minmax_closed_loop_n_in(void);
casadi_int rrr4_platform_design_na_proj_minmax_closed_loop_n_out(void);
casadi_real rrr4_platform_design_na_proj_minmax_closed_loop_default_in(casadi_int i);
const char* rrr4_platform_design_na_proj_minmax_closed_loop_name_in(casadi_int i);
const char* rrr4_platform_design_na_proj_minmax_closed_loop_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_na_proj_minmax_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_na_proj_minmax_closed_loop_sparsity_out(casadi_int i);
int rrr4_platform_design_na_proj_minmax_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_na_proj_minmax_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_na_proj_minmax_closed_loop_SZ_ARG 11
#define rrr4_platform_design_na_proj_minmax_closed_loop_SZ_RES 6
#define rrr4_platform_design_na_proj_minmax_closed_loop_SZ_IW 0
#define rrr4_platform_design_na_proj_minmax_closed_loop_SZ_W 258
int rrr4_platform_design_na_proj_preload_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_na_proj_preload_closed_loop_checkout(void);
void rrr4_platform_design_na_proj_preload_closed_loop_release(int mem);
void rrr4_platform_design_na_proj_preload_closed_loop_incref(void);
void rrr4_platform_design_na_proj_preload_closed_loop_decref(void);
casadi_int rrr4_platform_design_na_proj_preload_closed_loop_n_in(void);
casadi_int rrr4_platform_design_na_proj_preload_closed_loop_n_out(void);
casadi_real rrr4_platform_design_na_proj_preload_closed_loop_default_in(casadi_int i);
const char* rrr4_platform_design_na_proj_preload_closed_loop_name_in(casadi_int i);
const char* rrr4_platform_design_na_proj_preload_closed_loop_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_na_proj_preload_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_na_proj_preload_closed_loop_sparsity_out(casadi_int i);
int rrr4_platform_design_na_proj_preload_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_na_proj_preload_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_na_proj_preload_closed_loop_SZ_ARG 16
#define rrr4_platform_design_na_proj_preload_closed_loop_SZ_RES 8
#define rrr4_platform_design_na_proj_preload_closed_loop_SZ_IW 0
#define rrr4_platform_design_na_proj_preload_closed_loop_SZ_W 553
int rrr4_platform_design_apd_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_apd_closed_loop_checkout(void);
void rrr4_platform_design_apd_closed_loop_release(int mem);
void rrr4_platform_design_apd_closed_loop_incref(void);
void rrr4_platform_design_apd_closed_loop_decref(void);
casadi_int rrr4_platform_design_apd_closed_loop_n_in(void);
casadi_int rrr4_platform_design_apd_closed_loop_n_out(void);
casadi_real rrr4_platform_design_apd_closed_loop_default_in(casadi_int i);
const char* rrr4_platform_design_apd_closed_loop_name_in(casadi_int i);
const char* rrr4_platform_design_apd_closed_loop_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_apd_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_apd_closed_loop_sparsity_out(casadi_int i);
int rrr4_platform_design_apd_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_apd_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_apd_closed_loop_SZ_ARG 11
#define rrr4_platform_design_apd_closed_loop_SZ_RES 6
#define rrr4_platform_design_apd_closed_loop_SZ_IW 0
#define rrr4_platform_design_apd_closed_loop_SZ_W 231
int rrr4_platform_design_apd_minmax_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_apd_minmax_closed_loop_checkout(void);
void rrr4_platform_design_apd_minmax_closed_loop_release(int mem);
void rrr4_platform_design_apd_minmax_closed_loop_incref(void);
void rrr4_platform_design_apd_minmax_closed_loop_decref(void);
casadi_int rrr4_platform_design_apd_minmax_closed_loop_n_in(void);
casadi_int rrr4_platform_design_apd_minmax_closed_loop_n_out(void);
casadi_real rrr4_platform_design_apd_minmax_closed_loop_default_in(casadi_int i);
const char* rrr4_platform_design_apd_minmax_closed_loop_name_in(casadi_int i);
const char* rrr4_platform_design_apd_minmax_closed_loop_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_apd_minmax_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_apd_minmax_closed_loop_sparsity_out(casadi_int i);
int rrr4_platform_design_apd_minmax_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_apd_minmax_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_apd_minmax_closed_loop_SZ_ARG 11
#define rrr4_platform_design_apd_minmax_closed_loop_SZ_RES 6
#define rrr4_platform_design_apd_minmax_closed_loop_SZ_IW 0
#define rrr4_platform_design_apd_minmax_closed_loop_SZ_W 231
int rrr4_platform_design_apd_preload_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_apd_preload_closed_loop_checkout(void);
void rrr4_platform_design_apd_preload_closed_loop_release(int mem);
void rrr4_platform_design_apd_preload_closed_loop_incref(void);
void rrr4_platform_design_apd_preload_closed_loop_decref(void);
casadi_int rrr4_platform_design_apd_preload_closed_loop_n_in(void);
casadi_int rrr4_platform_design_apd_preload_closed_loop_n_out(void);
casadi_real rrr4_platform_design_apd_preload_closed_loop_default_in(casadi_int i);
const char* rrr4_platform_design_apd_preload_closed_loop_name_in(casadi_int i);
const char* rrr4_platform_design_apd_preload_closed_loop_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_apd_preload_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_apd_preload_closed_loop_sparsity_out(casadi_int i);
int rrr4_platform_design_apd_preload_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_apd_preload_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_apd_preload_closed_loop_SZ_ARG 16
#define rrr4_platform_design_apd_preload_closed_loop_SZ_RES 8
#define rrr4_platform_design_apd_preload_closed_loop_SZ_IW 0
#define rrr4_platform_design_apd_preload_closed_loop_SZ_W 512
int rrr4_platform_design_ctc_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_ctc_closed_loop_checkout(void);
void rrr4_platform_design_ctc_closed_loop_release(int mem);
void rrr4_platform_design_ctc_closed_loop_incref(void);
void rrr4_platform_design_ctc_closed_loop_decref(void);
casadi_int rrr4_platform_design_ctc_closed_loop_n_in(void);
casadi_int rrr4_platform_design_ctc_closed_loop_n_out(void);
casadi_real rrr4_platform_design_ctc_closed_loop_default_in(casadi_int i);
const char* rrr4_platform_design_ctc_closed_loop_name_in(casadi_int i);
const char* rrr4_platform_design_ctc_closed_loop_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_ctc_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_ctc_closed_loop_sparsity_out(casadi_int i);
int rrr4_platform_design_ctc_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_ctc_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_ctc_closed_loop_SZ_ARG 11
#define rrr4_platform_design_ctc_closed_loop_SZ_RES 6
#define rrr4_platform_design_ctc_closed_loop_SZ_IW 0
#define rrr4_platform_design_ctc_closed_loop_SZ_W 231
int rrr4_platform_design_ctc_minmax_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_ctc_minmax_closed_loop_checkout(void);
void rrr4_platform_design_ctc_minmax_closed_loop_release(int mem);
void rrr4_platform_design_ctc_minmax_closed_loop_incref(void);
void rrr4_platform_design_ctc_minmax_closed_loop_decref(void);
casadi_int rrr4_platform_design_ctc_minmax_closed_loop_n_in(void);
casadi_int rrr4_platform_design_ctc_minmax_closed_loop_n_out(void);
casadi_real rrr4_platform_design_ctc_minmax_closed_loop_default_in(casadi_int i);
const char* rrr4_platform_design_ctc_minmax_closed_loop_name_in(casadi_int i);
const char* rrr4_platform_design_ctc_minmax_closed_loop_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_ctc_minmax_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_ctc_minmax_closed_loop_sparsity_out(casadi_int i);
int rrr4_platform_design_ctc_minmax_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_ctc_minmax_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_ctc_minmax_closed_loop_SZ_ARG 11
#define rrr4_platform_design_ctc_minmax_closed_loop_SZ_RES 6
#define rrr4_platform_design_ctc_minmax_closed_loop_SZ_IW 0
#define rrr4_platform_design_ctc_minmax_closed_loop_SZ_W 231
int rrr4_platform_design_ctc_preload_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_ctc_preload_closed_loop_checkout(void);
void rrr4_platform_design_ctc_preload_closed_loop_release(int mem);
void rrr4_platform_design_ctc_preload_closed_loop_incref(void);
void rrr4_platform_design_ctc_preload_closed_loop_decref(void);
casadi_int rrr4_platform_design_ctc_preload_closed_loop_n_in(void);
casadi_int rrr4_platform_design_ctc_preload_closed_loop_n_out(void);
casadi_real rrr4_platform_design_ctc_preload_closed_loop_default_in(casadi_int i);
const char* rrr4_platform_design_ctc_preload_closed_loop_name_in(casadi_int i);
const char* rrr4_platform_design_ctc_preload_closed_loop_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_ctc_preload_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_ctc_preload_closed_loop_sparsity_out(casadi_int i);
int rrr4_platform_design_ctc_preload_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_ctc_preload_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_ctc_preload_closed_loop_SZ_ARG 16
#define rrr4_platform_design_ctc_preload_closed_loop_SZ_RES 8
#define rrr4_platform_design_ctc_preload_closed_loop_SZ_IW 0
#define rrr4_platform_design_ctc_preload_closed_loop_SZ_W 508
int rrr4_platform_design_lqr_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_lqr_closed_loop_checkout(void);
void rrr4_platform_design_lqr_closed_loop_release(int mem);
void rrr4_platform_design_lqr_closed_loop_incref(void);
void rrr4_platform_design_lqr_closed_loop_decref(void);
casadi_int rrr4_platform_design_lqr_closed_loop_n_in(void);
casadi_int rrr4_platform_design_lqr_closed_loop_n_out(void);
casadi_real rrr4_platform_design_lqr_closed_loop_default_in(casadi_int i);
const char* rrr4_platform_design_lqr_closed_loop_name_in(casadi_int i);
const char* rrr4_platform_design_lqr_closed_loop_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_lqr_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_lqr_closed_loop_sparsity_out(casadi_int i);
int rrr4_platform_design_lqr_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_lqr_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_lqr_closed_loop_SZ_ARG 13
#define rrr4_platform_design_lqr_closed_loop_SZ_RES 6
#define rrr4_platform_design_lqr_closed_loop_SZ_IW 0
#define rrr4_platform_design_lqr_closed_loop_SZ_W 231
int rrr4_platform_design_lqr_minmax_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_lqr_minmax_closed_loop_checkout(void);
void rrr4_platform_design_lqr_minmax_closed_loop_release(int mem);
void rrr4_platform_design_lqr_minmax_closed_loop_incref(void);
void rrr4_platform_design_lqr_minmax_closed_loop_decref(void);
casadi_int rrr4_platform_design_lqr_minmax_closed_loop_n_in(void);
casadi_int rrr4_platform_design_lqr_minmax_closed_loop_n_out(void);
casadi_real rrr4_platform_design_lqr_minmax_closed_loop_default_in(casadi_int i);
const char* rrr4_platform_design_lqr_minmax_closed_loop_name_in(casadi_int i);
const char* rrr4_platform_design_lqr_minmax_closed_loop_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_lqr_minmax_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_lqr_minmax_closed_loop_sparsity_out(casadi_int i);
int rrr4_platform_design_lqr_minmax_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_lqr_minmax_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_lqr_minmax_closed_loop_SZ_ARG 13
#define rrr4_platform_design_lqr_minmax_closed_loop_SZ_RES 6
#define rrr4_platform_design_lqr_minmax_closed_loop_SZ_IW 0
#define rrr4_platform_design_lqr_minmax_closed_loop_SZ_W 231
int rrr4_platform_design_lqr_preload_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_lqr_preload_closed_loop_checkout(void);
void rrr4_platform_design_lqr_preload_closed_loop_release(int mem);
void rrr4_platform_design_lqr_preload_closed_loop_incref(void);
void rrr4_platform_design_lqr_preload_closed_loop_decref(void);
casadi_int rrr4_platform_design_lqr_preload_closed_loop_n_in(void);
casadi_int rrr4_platform_design_lqr_preload_closed_loop_n_out(void);
casadi_real rrr4_platform_design_lqr_preload_closed_loop_default_in(casadi_int i);
const char* rrr4_platform_design_lqr_preload_closed_loop_name_in(casadi_int i);
const char* rrr4_platform_design_lqr_preload_closed_loop_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_lqr_preload_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_lqr_preload_closed_loop_sparsity_out(casadi_int i);
int rrr4_platform_design_lqr_preload_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_lqr_preload_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_lqr_preload_closed_loop_SZ_ARG 18
#define rrr4_platform_design_lqr_preload_closed_loop_SZ_RES 8
#define rrr4_platform_design_lqr_preload_closed_loop_SZ_IW 0
#define rrr4_platform_design_lqr_preload_closed_loop_SZ_W 473
int rrr4_platform_design_path_coefficients(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_path_coefficients_checkout(void);
void rrr4_platform_design_path_coefficients_release(int mem);
void rrr4_platform_design_path_coefficients_incref(void);
void rrr4_platform_design_path_coefficients_decref(void);
casadi_int rrr4_platform_design_path_coefficients_n_in(void);
casadi_int rrr4_platform_design_path_coefficients_n_out(void);
casadi_real rrr4_platform_design_path_coefficients_default_in(casadi_int i);
const char* rrr4_platform_design_path_coefficients_name_in(casadi_int i);
const char* rrr4_platform_design_path_coefficients_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_path_coefficients_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_path_coefficients_sparsity_out(casadi_int i);
int rrr4_platform_design_path_coefficients_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_path_coefficients_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_path_coefficients_SZ_ARG 6
#define rrr4_platform_design_path_coefficients_SZ_RES 9
#define rrr4_platform_design_path_coefficients_SZ_IW 0
#define rrr4_platform_design_path_coefficients_SZ_W 0
int rrr4_platform_design_path_mvc(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_path_mvc_checkout(void);
void rrr4_platform_design_path_mvc_release(int mem);
void rrr4_platform_design_path_mvc_incref(void);
void rrr4_platform_design_path_mvc_decref(void);
casadi_int rrr4_platform_design_path_mvc_n_in(void);
casadi_int rrr4_platform_design_path_mvc_n_out(void);
casadi_real rrr4_platform_design_path_mvc_default_in(casadi_int i);
const char* rrr4_platform_design_path_mvc_name_in(casadi_int i);
const char* rrr4_platform_design_path_mvc_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_path_mvc_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_path_mvc_sparsity_out(casadi_int i);
int rrr4_platform_design_path_mvc_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_path_mvc_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_path_mvc_SZ_ARG 2
#define rrr4_platform_design_path_mvc_SZ_RES 1
#define rrr4_platform_design_path_mvc_SZ_IW 0
#define rrr4_platform_design_path_mvc_SZ_W 0
int rrr4_platform_design_path_backward(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_path_backward_checkout(void);
void rrr4_platform_design_path_backward_release(int mem);
void rrr4_platform_design_path_backward_incref(void);
void rrr4_platform_design_path_backward_decref(void);
casadi_int rrr4_platform_design_path_backward_n_in(void);
casadi_int rrr4_platform_design_path_backward_n_out(void);
casadi_real rrr4_platform_design_path_backward_default_in(casadi_int i);
const char* rrr4_platform_design_path_backward_name_in(casadi_int i);
const char* rrr4_platform_design_path_backward_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_path_backward_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_path_backward_sparsity_out(casadi_int i);
int rrr4_platform_design_path_backward_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_path_backward_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_path_backward_SZ_ARG 22
#define rrr4_platform_design_path_backward_SZ_RES 9
#define rrr4_platform_design_path_backward_SZ_IW 0
#define rrr4_platform_design_path_backward_SZ_W 563
int rrr4_platform_design_path_forward(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_path_forward_checkout(void);
void rrr4_platform_design_path_forward_release(int mem);
void rrr4_platform_design_path_forward_incref(void);
void rrr4_platform_design_path_forward_decref(void);
casadi_int rrr4_platform_design_path_forward_n_in(void);
casadi_int rrr4_platform_design_path_forward_n_out(void);
casadi_real rrr4_platform_design_path_forward_default_in(casadi_int i);
const char* rrr4_platform_design_path_forward_name_in(casadi_int i);
const char* rrr4_platform_design_path_forward_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_path_forward_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_path_forward_sparsity_out(casadi_int i);
int rrr4_platform_design_path_forward_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_path_forward_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_path_forward_SZ_ARG 10
#define rrr4_platform_design_path_forward_SZ_RES 6
#define rrr4_platform_design_path_forward_SZ_IW 0
#define rrr4_platform_design_path_forward_SZ_W 154
int rrr4_platform_design_path_torques(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_path_torques_checkout(void);
void rrr4_platform_design_path_torques_release(int mem);
void rrr4_platform_design_path_torques_incref(void);
void rrr4_platform_design_path_torques_decref(void);
casadi_int rrr4_platform_design_path_torques_n_in(void);
casadi_int rrr4_platform_design_path_torques_n_out(void);
casadi_real rrr4_platform_design_path_torques_default_in(casadi_int i);
const char* rrr4_platform_design_path_torques_name_in(casadi_int i);
const char* rrr4_platform_design_path_torques_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_path_torques_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_path_torques_sparsity_out(casadi_int i);
int rrr4_platform_design_path_torques_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_path_torques_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_path_torques_SZ_ARG 5
#define rrr4_platform_design_path_torques_SZ_RES 4
#define rrr4_platform_design_path_torques_SZ_IW 0
#define rrr4_platform_design_path_torques_SZ_W 0
int rrr4_platform_design_forward_dynamics_jacobians(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_forward_dynamics_jacobians_checkout(void);
void rrr4_platform_design_forward_dynamics_jacobians_release(int mem);
void rrr4_platform_design_forward_dynamics_jacobians_incref(void);
void rrr4_platform_design_forward_dynamics_jacobians_decref(void);
casadi_int rrr4_platform_design_forward_dynamics_jacobians_n_in(void);
casadi_int rrr4_platform_design_forward_dynamics_jacobians_n_out(void);
casadi_real rrr4_platform_design_forward_dynamics_jacobians_default_in(casadi_int i);
const char* rrr4_platform_design_forward_dynamics_jacobians_name_in(casadi_int i);
const char* rrr4_platform_design_forward_dynamics_jacobians_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_forward_dynamics_jacobians_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_forward_dynamics_jacobians_sparsity_out(casadi_int i);
int rrr4_platform_design_forward_dynamics_jacobians_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_forward_dynamics_jacobians_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_forward_dynamics_jacobians_SZ_ARG 5
#define rrr4_platform_design_forward_dynamics_jacobians_SZ_RES 6
#define rrr4_platform_design_forward_dynamics_jacobians_SZ_IW 0
#define rrr4_platform_design_forward_dynamics_jacobians_SZ_W 0
int rrr4_platform_design_inverse_dynamics(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_inverse_dynamics_checkout(void);
void rrr4_platform_design_inverse_dynamics_release(int mem);
void rrr4_platform_design_inverse_dynamics_incref(void);
void rrr4_platform_design_inverse_dynamics_decref(void);
casadi_int rrr4_platform_design_inverse_dynamics_n_in(void);
casadi_int rrr4_platform_design_inverse_dynamics_n_out(void);
casadi_real rrr4_platform_design_inverse_dynamics_default_in(casadi_int i);
const char* rrr4_platform_design_inverse_dynamics_name_in(casadi_int i);
const char* rrr4_platform_design_inverse_dynamics_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_inverse_dynamics_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_inverse_dynamics_sparsity_out(casadi_int i);
int rrr4_platform_design_inverse_dynamics_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_inverse_dynamics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_inverse_dynamics_SZ_ARG 5
#define rrr4_platform_design_inverse_dynamics_SZ_RES 2
#define rrr4_platform_design_inverse_dynamics_SZ_IW 0
#define rrr4_platform_design_inverse_dynamics_SZ_W 0
int rrr4_platform_design_inverse_dynamics_jacobians(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_inverse_dynamics_jacobians_checkout(void);
void rrr4_platform_design_inverse_dynamics_jacobians_release(int mem);
void rrr4_platform_design_inverse_dynamics_jacobians_incref(void);
void rrr4_platform_design_inverse_dynamics_jacobians_decref(void);
casadi_int rrr4_platform_design_inverse_dynamics_jacobians_n_in(void);
casadi_int rrr4_platform_design_inverse_dynamics_jacobians_n_out(void);
casadi_real rrr4_platform_design_inverse_dynamics_jacobians_default_in(casadi_int i);
const char* rrr4_platform_design_inverse_dynamics_jacobians_name_in(casadi_int i);
const char* rrr4_platform_design_inverse_dynamics_jacobians_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_inverse_dynamics_jacobians_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_inverse_dynamics_jacobians_sparsity_out(casadi_int i);
int rrr4_platform_design_inverse_dynamics_jacobians_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_inverse_dynamics_jacobians_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_inverse_dynamics_jacobians_SZ_ARG 5
#define rrr4_platform_design_inverse_dynamics_jacobians_SZ_RES 4
#define rrr4_platform_design_inverse_dynamics_jacobians_SZ_IW 0
#define rrr4_platform_design_inverse_dynamics_jacobians_SZ_W 0
int rrr4_platform_design_sampled_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_sampled_step_checkout(void);
void rrr4_platform_design_sampled_step_release(int mem);
void rrr4_platform_design_sampled_step_incref(void);
void rrr4_platform_design_sampled_step_decref(void);
casadi_int rrr4_platform_design_sampled_step_n_in(void);
casadi_int rrr4_platform_design_sampled_step_n_out(void);
casadi_real rrr4_platform_design_sampled_step_default_in(casadi_int i);
const char* rrr4_platform_design_sampled_step_name_in(casadi_int i);
const char* rrr4_platform_design_sampled_step_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_sampled_step_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_sampled_step_sparsity_out(casadi_int i);
int rrr4_platform_design_sampled_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_sampled_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_sampled_step_SZ_ARG 10
#define rrr4_platform_design_sampled_step_SZ_RES 4
#define rrr4_platform_design_sampled_step_SZ_IW 0
#define rrr4_platform_design_sampled_step_SZ_W 158
int rrr4_platform_design_sampled_step_jacobians(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_sampled_step_jacobians_checkout(void);
void rrr4_platform_design_sampled_step_jacobians_release(int mem);
void rrr4_platform_design_sampled_step_jacobians_incref(void);
void rrr4_platform_design_sampled_step_jacobians_decref(void);
casadi_int rrr4_platform_design_sampled_step_jacobians_n_in(void);
casadi_int rrr4_platform_design_sampled_step_jacobians_n_out(void);
casadi_real rrr4_platform_design_sampled_step_jacobians_default_in(casadi_int i);
const char* rrr4_platform_design_sampled_step_jacobians_name_in(casadi_int i);
const char* rrr4_platform_design_sampled_step_jacobians_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_sampled_step_jacobians_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_sampled_step_jacobians_sparsity_out(casadi_int i);
int rrr4_platform_design_sampled_step_jacobians_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_sampled_step_jacobians_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_sampled_step_jacobians_SZ_ARG 10
#define rrr4_platform_design_sampled_step_jacobians_SZ_RES 10
#define rrr4_platform_design_sampled_step_jacobians_SZ_IW 11
#define rrr4_platform_design_sampled_step_jacobians_SZ_W 1698
int rrr4_platform_design_Ge(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_Ge_checkout(void);
void rrr4_platform_design_Ge_release(int mem);
void rrr4_platform_design_Ge_incref(void);
void rrr4_platform_design_Ge_decref(void);
casadi_int rrr4_platform_design_Ge_n_in(void);
casadi_int rrr4_platform_design_Ge_n_out(void);
casadi_real rrr4_platform_design_Ge_default_in(casadi_int i);
const char* rrr4_platform_design_Ge_name_in(casadi_int i);
const char* rrr4_platform_design_Ge_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_Ge_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_Ge_sparsity_out(casadi_int i);
int rrr4_platform_design_Ge_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_Ge_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_Ge_SZ_ARG 3
#define rrr4_platform_design_Ge_SZ_RES 2
#define rrr4_platform_design_Ge_SZ_IW 0
#define rrr4_platform_design_Ge_SZ_W 0
int rrr4_platform_design_kinetic_energy(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_kinetic_energy_checkout(void);
void rrr4_platform_design_kinetic_energy_release(int mem);
void rrr4_platform_design_kinetic_energy_incref(void);
void rrr4_platform_design_kinetic_energy_decref(void);
casadi_int rrr4_platform_design_kinetic_energy_n_in(void);
casadi_int rrr4_platform_design_kinetic_energy_n_out(void);
casadi_real rrr4_platform_design_kinetic_energy_default_in(casadi_int i);
const char* rrr4_platform_design_kinetic_energy_name_in(casadi_int i);
const char* rrr4_platform_design_kinetic_energy_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_kinetic_energy_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_kinetic_energy_sparsity_out(casadi_int i);
int rrr4_platform_design_kinetic_energy_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_kinetic_energy_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_kinetic_energy_SZ_ARG 4
#define rrr4_platform_design_kinetic_energy_SZ_RES 1
#define rrr4_platform_design_kinetic_energy_SZ_IW 0
#define rrr4_platform_design_kinetic_energy_SZ_W 0
int rrr4_platform_design_potential_energy(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rrr4_platform_design_potential_energy_checkout(void);
void rrr4_platform_design_potential_energy_release(int mem);
void rrr4_platform_design_potential_energy_incref(void);
void rrr4_platform_design_potential_energy_decref(void);
casadi_int rrr4_platform_design_potential_energy_n_in(void);
casadi_int rrr4_platform_design_potential_energy_n_out(void);
casadi_real rrr4_platform_design_potential_energy_default_in(casadi_int i);
const char* rrr4_platform_design_potential_energy_name_in(casadi_int i);
const char* rrr4_platform_design_potential_energy_name_out(casadi_int i);
const casadi_int* rrr4_platform_design_potential_energy_sparsity_in(casadi_int i);
const casadi_int* rrr4_platform_design_potential_energy_sparsity_out(casadi_int i);
int rrr4_platform_design_potential_energy_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rrr4_platform_design_potential_energy_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rrr4_platform_design_potential_energy_SZ_ARG 2
#define rrr4_platform_design_potential_energy_SZ_RES 1
#define rrr4_platform_design_potential_energy_SZ_IW 0
#define rrr4_platform_design_potential_energy_SZ_W 0
void rrr4_platform_design_casadi_version(int* major, int* minor, int* patch);
int rrr4_platform_design_casadi_int_size(void);
int rrr4_platform_design_casadi_real_size(void);
#ifdef __cplusplus
} /* extern "C" */
#endif
