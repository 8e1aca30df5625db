/* pm2dof generated code for model 'rpr3_platform' (3 legs, friction 'smooth_sign').
 * Written by `pm2dof derive` from the model file; do not edit.
 *
 * Every function follows CasADi's C API: int f(const double** arg, double** res,
 * long long* iw, double* w, int mem), with work sizes from f_work(). All inputs and
 * outputs are dense; matrices are stored ROW-MAJOR (flattened row by row). SI units.
 *
 * q     = [qa_1..qa_3, qb_1..qb_3]  absolute joint angles, rad (eq. 3 order)
 * qa    = [qa_1..qa_3]  measured active angles, rad
 * xe    = [x, y, phi] pose (m, angles in rad);  xed, xrd, xrdd: its rates and accelerations
 * theta = [alpha1, alpha2, alpha3, beta1, beta2, beta3, gamma1, gamma2, gamma3, m_p, mx_p, my_p, I_p, fv1, fv2, fv3, fc1, fc2, fc3]
 * sing  = [the legs' type I measure (min over the legs), sigma_min of S with unit rows
 *         over sqrt(n/3) (type II, actuation)]
 *
 * Functions (inputs -> outputs, element counts):
 *   rpr3_platform_ik(xe[3]) -> (q[6])
 *   rpr3_platform_fk(qa[3]) -> (xe[3], residual[3])
 *   rpr3_platform_H(q[6]) -> (H[6])
 *   rpr3_platform_A(q[6]) -> (A[36])
 *   rpr3_platform_singularity(q[6]) -> (sin_ab[3])
 *   rpr3_platform_singularity_measures(q[6]) -> (sing[2])
 *   rpr3_platform_W(q[6]) -> (W[18], sing[2])
 *   rpr3_platform_S(q[6]) -> (S[9], sing[2])
 *   rpr3_platform_Wdot(q[6], xed[3]) -> (Wdot[18], sing[2])
 *   rpr3_platform_M(q[6], theta[19]) -> (M[36])
 *   rpr3_platform_C(q[6], qd[6], theta[19]) -> (C[36])
 *   rpr3_platform_Me(q[6], theta[19]) -> (Me[9], sing[2])
 *   rpr3_platform_Ce(q[6], xed[3], theta[19]) -> (Ce[9], sing[2])
 *   rpr3_platform_StF(q[6], xed[3], theta[19]) -> (StF[3], sing[2])
 *   rpr3_platform_Y(q[6], xed[3], xrd[3], xrdd[3]) -> (Y[57], sing[2])
 *   rpr3_platform_torque_splits(q[6], u[3], tau_max[3], preload_sign[3], preload[3]) -> (tau_min_norm[3], tau_min_max[3], min_max_ratio[1], tau_preload[3], preload_mode[1], sing[2])
 *   rpr3_platform_forward_dynamics(xe[3], xed[3], tau_a[3], theta[19]) -> (xedd[3], sing[2])
 *   rpr3_platform_na_step(state[25], qa[3], xd[3], xd_dot[3], xd_ddot[3], params[40]) -> (tau_a[3], state_next[25], status[1], diag[14])
 *   rpr3_platform_na_minmax_step(state[25], qa[3], xd[3], xd_dot[3], xd_ddot[3], params[40]) -> (tau_a[3], state_next[25], status[1], diag[14])
 *   rpr3_platform_na_preload_step(state[25], qa[3], xd[3], xd_dot[3], xd_ddot[3], params[40]) -> (tau_a[3], state_next[25], status[1], diag[14])
 *   rpr3_platform_na_proj_step(state[25], qa[3], xd[3], xd_dot[3], xd_ddot[3], params[40]) -> (tau_a[3], state_next[25], status[1], diag[14])
 *   rpr3_platform_na_proj_minmax_step(state[25], qa[3], xd[3], xd_dot[3], xd_ddot[3], params[40]) -> (tau_a[3], state_next[25], status[1], diag[14])
 *   rpr3_platform_na_proj_preload_step(state[25], qa[3], xd[3], xd_dot[3], xd_ddot[3], params[40]) -> (tau_a[3], state_next[25], status[1], diag[14])
 *   rpr3_platform_apd_step(state[25], qa[3], xd[3], xd_dot[3], xd_ddot[3], params[20]) -> (tau_a[3], state_next[25], status[1], diag[14])
 *   rpr3_platform_apd_minmax_step(state[25], qa[3], xd[3], xd_dot[3], xd_ddot[3], params[20]) -> (tau_a[3], state_next[25], status[1], diag[14])
 *   rpr3_platform_apd_preload_step(state[25], qa[3], xd[3], xd_dot[3], xd_ddot[3], params[20]) -> (tau_a[3], state_next[25], status[1], diag[14])
 *   rpr3_platform_ctc_step(state[25], qa[3], xd[3], xd_dot[3], xd_ddot[3], params[20]) -> (tau_a[3], state_next[25], status[1], diag[14])
 *   rpr3_platform_ctc_minmax_step(state[25], qa[3], xd[3], xd_dot[3], xd_ddot[3], params[20]) -> (tau_a[3], state_next[25], status[1], diag[14])
 *   rpr3_platform_ctc_preload_step(state[25], qa[3], xd[3], xd_dot[3], xd_ddot[3], params[20]) -> (tau_a[3], state_next[25], status[1], diag[14])
 *   rpr3_platform_lqr_step(state[25], qa[3], xd[3], xd_dot[3], xd_ddot[3], params[14], K[18], tau_ff[3]) -> (tau_a[3], state_next[25], status[1], diag[14])
 *   rpr3_platform_lqr_minmax_step(state[25], qa[3], xd[3], xd_dot[3], xd_ddot[3], params[14], K[18], tau_ff[3]) -> (tau_a[3], state_next[25], status[1], diag[14])
 *   rpr3_platform_lqr_preload_step(state[25], qa[3], xd[3], xd_dot[3], xd_ddot[3], params[14], K[18], tau_ff[3]) -> (tau_a[3], state_next[25], status[1], diag[14])
 *   rpr3_platform_plant_xedd(xe[3], xed[3], tau_a[3], plant[26]) -> (xedd[3])
 *   rpr3_platform_plant_step(x[6], tau_a[3], plant[26], h[1]) -> (x_next[6])
 *   rpr3_platform_measure(xe[3], plant[26]) -> (qa[3])
 *   rpr3_platform_na_closed_loop(x[31], u[9], p[66]) -> (x_next[31], y[29])
 *   rpr3_platform_na_minmax_closed_loop(x[31], u[9], p[66]) -> (x_next[31], y[29])
 *   rpr3_platform_na_preload_closed_loop(x[31], u[9], p[66]) -> (x_next[31], y[29])
 *   rpr3_platform_na_proj_closed_loop(x[31], u[9], p[66]) -> (x_next[31], y[29])
 *   rpr3_platform_na_proj_minmax_closed_loop(x[31], u[9], p[66]) -> (x_next[31], y[29])
 *   rpr3_platform_na_proj_preload_closed_loop(x[31], u[9], p[66]) -> (x_next[31], y[29])
 *   rpr3_platform_apd_closed_loop(x[31], u[9], p[46]) -> (x_next[31], y[29])
 *   rpr3_platform_apd_minmax_closed_loop(x[31], u[9], p[46]) -> (x_next[31], y[29])
 *   rpr3_platform_apd_preload_closed_loop(x[31], u[9], p[46]) -> (x_next[31], y[29])
 *   rpr3_platform_ctc_closed_loop(x[31], u[9], p[46]) -> (x_next[31], y[29])
 *   rpr3_platform_ctc_minmax_closed_loop(x[31], u[9], p[46]) -> (x_next[31], y[29])
 *   rpr3_platform_ctc_preload_closed_loop(x[31], u[9], p[46]) -> (x_next[31], y[29])
 *   rpr3_platform_lqr_closed_loop(x[31], u[30], p[40]) -> (x_next[31], y[29])
 *   rpr3_platform_lqr_minmax_closed_loop(x[31], u[30], p[40]) -> (x_next[31], y[29])
 *   rpr3_platform_lqr_preload_closed_loop(x[31], u[30], p[40]) -> (x_next[31], y[29])
 *   rpr3_platform_path_coefficients(p[3], dp[3], ddp[3], theta[19], tau_max[3]) -> (a[3], b[3], S[9], v1[3], N_min_norm[9], h_min_norm[3], N_min_max[9], h_min_max[3], sing[2])
 *   rpr3_platform_path_mvc(stage[35], params[20]) -> (x_mvc[1])
 *   rpr3_platform_path_backward(x_next_max[1], input[74], params[20]) -> (x_max[1], y[1])
 *   rpr3_platform_path_forward(x[1], input[75], params[20]) -> (x_next[1], y[6])
 *   rpr3_platform_path_torques(stage[35], sd[1], sdd[1], params[20], tau_max[3]) -> (u[3], tau_min_norm[3], tau_min_max[3], min_max_ratio[1])
 *   rpr3_platform_forward_dynamics_jacobians(xe[3], xed[3], tau_a[3], theta[19]) -> (xedd[3], d_xe[9], d_xed[9], d_tau_a[9], d_theta[57], sing[2])
 *   rpr3_platform_inverse_dynamics(xe[3], xed[3], xedd[3], theta[19]) -> (u[3], sing[2])
 *   rpr3_platform_inverse_dynamics_jacobians(xe[3], xed[3], xedd[3], theta[19]) -> (u[3], d_xe[9], d_xed[9], sing[2])
 *   rpr3_platform_sampled_step(x[6], tau_a[3], theta[19], T[1]) -> (x_next[6], sing[2])
 *   rpr3_platform_sampled_step_jacobians(x[6], tau_a[3], theta[19], T[1]) -> (x_next[6], d_x[36], d_tau_a[18], sing[2])
 *   rpr3_platform_Ge(q[6], theta[19]) -> (Ge[3], sing[2])
 *   rpr3_platform_kinetic_energy(xe[3], xed[3], theta[19]) -> (T[1])
 *   rpr3_platform_potential_energy(xe[3], theta[19]) -> (V[1])
 *
 * Flat vectors of the controllers, plant and closed loop (field[count], in order):
 *   ctrl_state: xe_prev[3], v[3], theta_hat[19]
 *   na_params: Kd[3], Q[3], Gamma[19], freeze_saturated[1], T[1], vel_alpha[1], sing_threshold[1], parallel_sing_threshold[1], tau_max[3], preload_sign[3], preload[3], closure_tol[1]
 *   apd_params: Kp[3], Kv[3], T[1], vel_alpha[1], sing_threshold[1], parallel_sing_threshold[1], tau_max[3], preload_sign[3], preload[3], closure_tol[1]
 *   ctc_params: Kp[3], Kv[3], T[1], vel_alpha[1], sing_threshold[1], parallel_sing_threshold[1], tau_max[3], preload_sign[3], preload[3], closure_tol[1]
 *   lqr_params: T[1], vel_alpha[1], sing_threshold[1], parallel_sing_threshold[1], tau_max[3], preload_sign[3], preload[3], closure_tol[1]
 *   cl_state: xe[3], xed[3], ctrl_state[25]
 *   cl_input: xd[3], xd_dot[3], xd_ddot[3]
 *   cl_output: xe[3], xed[3], tau_a[3], status[1], theta_hat[19]
 *   lqr_cl_input: xd[3], xd_dot[3], xd_ddot[3], K[18], tau_ff[3]
 *   plant: alpha[3], beta[3], gamma[3], m_p[1], mx_p[1], my_p[1], I_p[1], fv[3], fc[3], fs[3], stribeck_velocity[1], coulomb_smoothing_velocity[1], encoder_step[1], linear_encoder_step[1]
 *   path_stage: N[9], h[3], a[3], b[3], S[9], v1[3], rho[3], delta[1], x_cap[1]
 *   path_pair: stage[35], next[35], next_cap[1]
 *   path_backward_input: pair[71], same[1], x_in[1], x_out[1]
 *   path_forward_input: pair[71], x_next_max[1], same[1], x_in[1], x_out[1]
 *   path_forward_output: x[1], sdd[1], L[1], U[1], Z[1], arrival_ok[1]
 *   path_params: v_top[1], theta[19]
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

int rpr3_platform_ik(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_ik_checkout(void);
void rpr3_platform_ik_release(int mem);
void rpr3_platform_ik_incref(void);
void rpr3_platform_ik_decref(void);
casadi_int rpr3_platform_ik_n_in(void);
casadi_int rpr3_platform_ik_n_out(void);
casadi_real rpr3_platform_ik_default_in(casadi_int i);
const char* rpr3_platform_ik_name_in(casadi_int i);
const char* rpr3_platform_ik_name_out(casadi_int i);
const casadi_int* rpr3_platform_ik_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_ik_sparsity_out(casadi_int i);
int rpr3_platform_ik_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_ik_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_ik_SZ_ARG 1
#define rpr3_platform_ik_SZ_RES 1
#define rpr3_platform_ik_SZ_IW 0
#define rpr3_platform_ik_SZ_W 0
int rpr3_platform_fk(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_fk_checkout(void);
void rpr3_platform_fk_release(int mem);
void rpr3_platform_fk_incref(void);
void rpr3_platform_fk_decref(void);
casadi_int rpr3_platform_fk_n_in(void);
casadi_int rpr3_platform_fk_n_out(void);
casadi_real rpr3_platform_fk_default_in(casadi_int i);
const char* rpr3_platform_fk_name_in(casadi_int i);
const char* rpr3_platform_fk_name_out(casadi_int i);
const casadi_int* rpr3_platform_fk_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_fk_sparsity_out(casadi_int i);
int rpr3_platform_fk_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_fk_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_fk_SZ_ARG 1
#define rpr3_platform_fk_SZ_RES 2
#define rpr3_platform_fk_SZ_IW 0
#define rpr3_platform_fk_SZ_W 0
int rpr3_platform_H(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_H_checkout(void);
void rpr3_platform_H_release(int mem);
void rpr3_platform_H_incref(void);
void rpr3_platform_H_decref(void);
casadi_int rpr3_platform_H_n_in(void);
casadi_int rpr3_platform_H_n_out(void);
casadi_real rpr3_platform_H_default_in(casadi_int i);
const char* rpr3_platform_H_name_in(casadi_int i);
const char* rpr3_platform_H_name_out(casadi_int i);
const casadi_int* rpr3_platform_H_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_H_sparsity_out(casadi_int i);
int rpr3_platform_H_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_H_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_H_SZ_ARG 1
#define rpr3_platform_H_SZ_RES 1
#define rpr3_platform_H_SZ_IW 0
#define rpr3_platform_H_SZ_W 0
int rpr3_platform_A(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_A_checkout(void);
void rpr3_platform_A_release(int mem);
void rpr3_platform_A_incref(void);
void rpr3_platform_A_decref(void);
casadi_int rpr3_platform_A_n_in(void);
casadi_int rpr3_platform_A_n_out(void);
casadi_real rpr3_platform_A_default_in(casadi_int i);
const char* rpr3_platform_A_name_in(casadi_int i);
const char* rpr3_platform_A_name_out(casadi_int i);
const casadi_int* rpr3_platform_A_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_A_sparsity_out(casadi_int i);
int rpr3_platform_A_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_A_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_A_SZ_ARG 1
#define rpr3_platform_A_SZ_RES 1
#define rpr3_platform_A_SZ_IW 0
#define rpr3_platform_A_SZ_W 0
int rpr3_platform_singularity(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_singularity_checkout(void);
void rpr3_platform_singularity_release(int mem);
void rpr3_platform_singularity_incref(void);
void rpr3_platform_singularity_decref(void);
casadi_int rpr3_platform_singularity_n_in(void);
casadi_int rpr3_platform_singularity_n_out(void);
casadi_real rpr3_platform_singularity_default_in(casadi_int i);
const char* rpr3_platform_singularity_name_in(casadi_int i);
const char* rpr3_platform_singularity_name_out(casadi_int i);
const casadi_int* rpr3_platform_singularity_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_singularity_sparsity_out(casadi_int i);
int rpr3_platform_singularity_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_singularity_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_singularity_SZ_ARG 1
#define rpr3_platform_singularity_SZ_RES 1
#define rpr3_platform_singularity_SZ_IW 0
#define rpr3_platform_singularity_SZ_W 0
int rpr3_platform_singularity_measures(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_singularity_measures_checkout(void);
void rpr3_platform_singularity_measures_release(int mem);
void rpr3_platform_singularity_measures_incref(void);
void rpr3_platform_singularity_measures_decref(void);
casadi_int rpr3_platform_singularity_measures_n_in(void);
casadi_int rpr3_platform_singularity_measures_n_out(void);
casadi_real rpr3_platform_singularity_measures_default_in(casadi_int i);
const char* rpr3_platform_singularity_measures_name_in(casadi_int i);
const char* rpr3_platform_singularity_measures_name_out(casadi_int i);
const casadi_int* rpr3_platform_singularity_measures_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_singularity_measures_sparsity_out(casadi_int i);
int rpr3_platform_singularity_measures_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_singularity_measures_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_singularity_measures_SZ_ARG 1
#define rpr3_platform_singularity_measures_SZ_RES 1
#define rpr3_platform_singularity_measures_SZ_IW 0
#define rpr3_platform_singularity_measures_SZ_W 0
int rpr3_platform_W(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_W_checkout(void);
void rpr3_platform_W_release(int mem);
void rpr3_platform_W_incref(void);
void rpr3_platform_W_decref(void);
casadi_int rpr3_platform_W_n_in(void);
casadi_int rpr3_platform_W_n_out(void);
casadi_real rpr3_platform_W_default_in(casadi_int i);
const char* rpr3_platform_W_name_in(casadi_int i);
const char* rpr3_platform_W_name_out(casadi_int i);
const casadi_int* rpr3_platform_W_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_W_sparsity_out(casadi_int i);
int rpr3_platform_W_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_W_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_W_SZ_ARG 1
#define rpr3_platform_W_SZ_RES 2
#define rpr3_platform_W_SZ_IW 0
#define rpr3_platform_W_SZ_W 0
int rpr3_platform_S(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_S_checkout(void);
void rpr3_platform_S_release(int mem);
void rpr3_platform_S_incref(void);
void rpr3_platform_S_decref(void);
casadi_int rpr3_platform_S_n_in(void);
casadi_int rpr3_platform_S_n_out(void);
casadi_real rpr3_platform_S_default_in(casadi_int i);
const char* rpr3_platform_S_name_in(casadi_int i);
const char* rpr3_platform_S_name_out(casadi_int i);
const casadi_int* rpr3_platform_S_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_S_sparsity_out(casadi_int i);
int rpr3_platform_S_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_S_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_S_SZ_ARG 1
#define rpr3_platform_S_SZ_RES 2
#define rpr3_platform_S_SZ_IW 0
#define rpr3_platform_S_SZ_W 0
int rpr3_platform_Wdot(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_Wdot_checkout(void);
void rpr3_platform_Wdot_release(int mem);
void rpr3_platform_Wdot_incref(void);
void rpr3_platform_Wdot_decref(void);
casadi_int rpr3_platform_Wdot_n_in(void);
casadi_int rpr3_platform_Wdot_n_out(void);
casadi_real rpr3_platform_Wdot_default_in(casadi_int i);
const char* rpr3_platform_Wdot_name_in(casadi_int i);
const char* rpr3_platform_Wdot_name_out(casadi_int i);
const casadi_int* rpr3_platform_Wdot_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_Wdot_sparsity_out(casadi_int i);
int rpr3_platform_Wdot_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_Wdot_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_Wdot_SZ_ARG 2
#define rpr3_platform_Wdot_SZ_RES 2
#define rpr3_platform_Wdot_SZ_IW 0
#define rpr3_platform_Wdot_SZ_W 0
int rpr3_platform_M(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_M_checkout(void);
void rpr3_platform_M_release(int mem);
void rpr3_platform_M_incref(void);
void rpr3_platform_M_decref(void);
casadi_int rpr3_platform_M_n_in(void);
casadi_int rpr3_platform_M_n_out(void);
casadi_real rpr3_platform_M_default_in(casadi_int i);
const char* rpr3_platform_M_name_in(casadi_int i);
const char* rpr3_platform_M_name_out(casadi_int i);
const casadi_int* rpr3_platform_M_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_M_sparsity_out(casadi_int i);
int rpr3_platform_M_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_M_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_M_SZ_ARG 2
#define rpr3_platform_M_SZ_RES 1
#define rpr3_platform_M_SZ_IW 0
#define rpr3_platform_M_SZ_W 0
int rpr3_platform_C(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_C_checkout(void);
void rpr3_platform_C_release(int mem);
void rpr3_platform_C_incref(void);
void rpr3_platform_C_decref(void);
casadi_int rpr3_platform_C_n_in(void);
casadi_int rpr3_platform_C_n_out(void);
casadi_real rpr3_platform_C_default_in(casadi_int i);
const char* rpr3_platform_C_name_in(casadi_int i);
const char* rpr3_platform_C_name_out(casadi_int i);
const casadi_int* rpr3_platform_C_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_C_sparsity_out(casadi_int i);
int rpr3_platform_C_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_C_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_C_SZ_ARG 3
#define rpr3_platform_C_SZ_RES 1
#define rpr3_platform_C_SZ_IW 0
#define rpr3_platform_C_SZ_W 0
int rpr3_platform_Me(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_Me_checkout(void);
void rpr3_platform_Me_release(int mem);
void rpr3_platform_Me_incref(void);
void rpr3_platform_Me_decref(void);
casadi_int rpr3_platform_Me_n_in(void);
casadi_int rpr3_platform_Me_n_out(void);
casadi_real rpr3_platform_Me_default_in(casadi_int i);
const char* rpr3_platform_Me_name_in(casadi_int i);
const char* rpr3_platform_Me_name_out(casadi_int i);
const casadi_int* rpr3_platform_Me_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_Me_sparsity_out(casadi_int i);
int rpr3_platform_Me_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_Me_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_Me_SZ_ARG 2
#define rpr3_platform_Me_SZ_RES 2
#define rpr3_platform_Me_SZ_IW 0
#define rpr3_platform_Me_SZ_W 0
int rpr3_platform_Ce(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_Ce_checkout(void);
void rpr3_platform_Ce_release(int mem);
void rpr3_platform_Ce_incref(void);
void rpr3_platform_Ce_decref(void);
casadi_int rpr3_platform_Ce_n_in(void);
casadi_int rpr3_platform_Ce_n_out(void);
casadi_real rpr3_platform_Ce_default_in(casadi_int i);
const char* rpr3_platform_Ce_name_in(casadi_int i);
const char* rpr3_platform_Ce_name_out(casadi_int i);
const casadi_int* rpr3_platform_Ce_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_Ce_sparsity_out(casadi_int i);
int rpr3_platform_Ce_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_Ce_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_Ce_SZ_ARG 3
#define rpr3_platform_Ce_SZ_RES 2
#define rpr3_platform_Ce_SZ_IW 0
#define rpr3_platform_Ce_SZ_W 0
int rpr3_platform_StF(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_StF_checkout(void);
void rpr3_platform_StF_release(int mem);
void rpr3_platform_StF_incref(void);
void rpr3_platform_StF_decref(void);
casadi_int rpr3_platform_StF_n_in(void);
casadi_int rpr3_platform_StF_n_out(void);
casadi_real rpr3_platform_StF_default_in(casadi_int i);
const char* rpr3_platform_StF_name_in(casadi_int i);
const char* rpr3_platform_StF_name_out(casadi_int i);
const casadi_int* rpr3_platform_StF_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_StF_sparsity_out(casadi_int i);
int rpr3_platform_StF_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_StF_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_StF_SZ_ARG 3
#define rpr3_platform_StF_SZ_RES 2
#define rpr3_platform_StF_SZ_IW 0
#define rpr3_platform_StF_SZ_W 0
int rpr3_platform_Y(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_Y_checkout(void);
void rpr3_platform_Y_release(int mem);
void rpr3_platform_Y_incref(void);
void rpr3_platform_Y_decref(void);
casadi_int rpr3_platform_Y_n_in(void);
casadi_int rpr3_platform_Y_n_out(void);
casadi_real rpr3_platform_Y_default_in(casadi_int i);
const char* rpr3_platform_Y_name_in(casadi_int i);
const char* rpr3_platform_Y_name_out(casadi_int i);
const casadi_int* rpr3_platform_Y_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_Y_sparsity_out(casadi_int i);
int rpr3_platform_Y_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_Y_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_Y_SZ_ARG 4
#define rpr3_platform_Y_SZ_RES 2
#define rpr3_platform_Y_SZ_IW 0
#define rpr3_platform_Y_SZ_W 0
int rpr3_platform_torque_splits(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_torque_splits_checkout(void);
void rpr3_platform_torque_splits_release(int mem);
void rpr3_platform_torque_splits_incref(void);
void rpr3_platform_torque_splits_decref(void);
casadi_int rpr3_platform_torque_splits_n_in(void);
casadi_int rpr3_platform_torque_splits_n_out(void);
casadi_real rpr3_platform_torque_splits_default_in(casadi_int i);
const char* rpr3_platform_torque_splits_name_in(casadi_int i);
const char* rpr3_platform_torque_splits_name_out(casadi_int i);
const casadi_int* rpr3_platform_torque_splits_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_torque_splits_sparsity_out(casadi_int i);
int rpr3_platform_torque_splits_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_torque_splits_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_torque_splits_SZ_ARG 10
#define rpr3_platform_torque_splits_SZ_RES 8
#define rpr3_platform_torque_splits_SZ_IW 0
#define rpr3_platform_torque_splits_SZ_W 82
int rpr3_platform_forward_dynamics(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_forward_dynamics_checkout(void);
void rpr3_platform_forward_dynamics_release(int mem);
void rpr3_platform_forward_dynamics_incref(void);
void rpr3_platform_forward_dynamics_decref(void);
casadi_int rpr3_platform_forward_dynamics_n_in(void);
casadi_int rpr3_platform_forward_dynamics_n_out(void);
casadi_real rpr3_platform_forward_dynamics_default_in(casadi_int i);
const char* rpr3_platform_forward_dynamics_name_in(casadi_int i);
const char* rpr3_platform_forward_dynamics_name_out(casadi_int i);
const casadi_int* rpr3_platform_forward_dynamics_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_forward_dynamics_sparsity_out(casadi_int i);
int rpr3_platform_forward_dynamics_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_forward_dynamics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_forward_dynamics_SZ_ARG 4
#define rpr3_platform_forward_dynamics_SZ_RES 2
#define rpr3_platform_forward_dynamics_SZ_IW 0
#define rpr3_platform_forward_dynamics_SZ_W 0
int rpr3_platform_na_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_na_step_checkout(void);
void rpr3_platform_na_step_release(int mem);
void rpr3_platform_na_step_incref(void);
void rpr3_platform_na_step_decref(void);
casadi_int rpr3_platform_na_step_n_in(void);
casadi_int rpr3_platform_na_step_n_out(void);
casadi_real rpr3_platform_na_step_default_in(casadi_int i);
const char* rpr3_platform_na_step_name_in(casadi_int i);
const char* rpr3_platform_na_step_name_out(casadi_int i);
const casadi_int* rpr3_platform_na_step_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_na_step_sparsity_out(casadi_int i);
int rpr3_platform_na_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_na_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_na_step_SZ_ARG 6
#define rpr3_platform_na_step_SZ_RES 4
#define rpr3_platform_na_step_SZ_IW 0
#define rpr3_platform_na_step_SZ_W 0
int rpr3_platform_na_minmax_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_na_minmax_step_checkout(void);
void rpr3_platform_na_minmax_step_release(int mem);
void rpr3_platform_na_minmax_step_incref(void);
void rpr3_platform_na_minmax_step_decref(void);
casadi_int rpr3_platform_na_minmax_step_n_in(void);
casadi_int rpr3_platform_na_minmax_step_n_out(void);
casadi_real rpr3_platform_na_minmax_step_default_in(casadi_int i);
const char* rpr3_platform_na_minmax_step_name_in(casadi_int i);
const char* rpr3_platform_na_minmax_step_name_out(casadi_int i);
const casadi_int* rpr3_platform_na_minmax_step_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_na_minmax_step_sparsity_out(casadi_int i);
int rpr3_platform_na_minmax_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_na_minmax_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_na_minmax_step_SZ_ARG 6
#define rpr3_platform_na_minmax_step_SZ_RES 4
#define rpr3_platform_na_minmax_step_SZ_IW 0
#define rpr3_platform_na_minmax_step_SZ_W 0
int rpr3_platform_na_preload_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_na_preload_step_checkout(void);
void rpr3_platform_na_preload_step_release(int mem);
void rpr3_platform_na_preload_step_incref(void);
void rpr3_platform_na_preload_step_decref(void);
casadi_int rpr3_platform_na_preload_step_n_in(void);
casadi_int rpr3_platform_na_preload_step_n_out(void);
casadi_real rpr3_platform_na_preload_step_default_in(casadi_int i);
const char* rpr3_platform_na_preload_step_name_in(casadi_int i);
const char* rpr3_platform_na_preload_step_name_out(casadi_int i);
const casadi_int* rpr3_platform_na_preload_step_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_na_preload_step_sparsity_out(casadi_int i);
int rpr3_platform_na_preload_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_na_preload_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_na_preload_step_SZ_ARG 11
#define rpr3_platform_na_preload_step_SZ_RES 6
#define rpr3_platform_na_preload_step_SZ_IW 0
#define rpr3_platform_na_preload_step_SZ_W 82
int rpr3_platform_na_proj_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_na_proj_step_checkout(void);
void rpr3_platform_na_proj_step_release(int mem);
void rpr3_platform_na_proj_step_incref(void);
void rpr3_platform_na_proj_step_decref(void);
casadi_int rpr3_platform_na_proj_step_n_in(void);
casadi_int rpr3_platform_na_proj_step_n_out(void);
casadi_real rpr3_platform_na_proj_step_default_in(casadi_int i);
const char* rpr3_platform_na_proj_step_name_in(casadi_int i);
const char* rpr3_platform_na_proj_step_name_out(casadi_int i);
const casadi_int* rpr3_platform_na_proj_step_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_na_proj_step_sparsity_out(casadi_int i);
int rpr3_platform_na_proj_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_na_proj_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_na_proj_step_SZ_ARG 6
#define rpr3_platform_na_proj_step_SZ_RES 4
#define rpr3_platform_na_proj_step_SZ_IW 0
#define rpr3_platform_na_proj_step_SZ_W 0
int rpr3_platform_na_proj_minmax_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_na_proj_minmax_step_checkout(void);
void rpr3_platform_na_proj_minmax_step_release(int mem);
void rpr3_platform_na_proj_minmax_step_incref(void);
void rpr3_platform_na_proj_minmax_step_decref(void);
casadi_int rpr3_platform_na_proj_minmax_step_n_in(void);
casadi_int rpr3_platform_na_proj_minmax_step_n_out(void);
casadi_real rpr3_platform_na_proj_minmax_step_default_in(casadi_int i);
const char* rpr3_platform_na_proj_minmax_step_name_in(casadi_int i);
const char* rpr3_platform_na_proj_minmax_step_name_out(casadi_int i);
const casadi_int* rpr3_platform_na_proj_minmax_step_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_na_proj_minmax_step_sparsity_out(casadi_int i);
int rpr3_platform_na_proj_minmax_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_na_proj_minmax_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_na_proj_minmax_step_SZ_ARG 6
#define rpr3_platform_na_proj_minmax_step_SZ_RES 4
#define rpr3_platform_na_proj_minmax_step_SZ_IW 0
#define rpr3_platform_na_proj_minmax_step_SZ_W 0
int rpr3_platform_na_proj_preload_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_na_proj_preload_step_checkout(void);
void rpr3_platform_na_proj_preload_step_release(int mem);
void rpr3_platform_na_proj_preload_step_incref(void);
void rpr3_platform_na_proj_preload_step_decref(void);
casadi_int rpr3_platform_na_proj_preload_step_n_in(void);
casadi_int rpr3_platform_na_proj_preload_step_n_out(void);
casadi_real rpr3_platform_na_proj_preload_step_default_in(casadi_int i);
const char* rpr3_platform_na_proj_preload_step_name_in(casadi_int i);
const char* rpr3_platform_na_proj_preload_step_name_out(casadi_int i);
const casadi_int* rpr3_platform_na_proj_preload_step_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_na_proj_preload_step_sparsity_out(casadi_int i);
int rpr3_platform_na_proj_preload_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_na_proj_preload_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_na_proj_preload_step_SZ_ARG 11
#define rpr3_platform_na_proj_preload_step_SZ_RES 6
#define rpr3_platform_na_proj_preload_step_SZ_IW 0
#define rpr3_platform_na_proj_preload_step_SZ_W 82
int rpr3_platform_apd_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_apd_step_checkout(void);
void rpr3_platform_apd_step_release(int mem);
void rpr3_platform_apd_step_incref(void);
void rpr3_platform_apd_step_decref(void);
casadi_int rpr3_platform_apd_step_n_in(void);
casadi_int rpr3_platform_apd_step_n_out(void);
casadi_real rpr3_platform_apd_step_default_in(casadi_int i);
const char* rpr3_platform_apd_step_name_in(casadi_int i);
const char* rpr3_platform_apd_step_name_out(casadi_int i);
const casadi_int* rpr3_platform_apd_step_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_apd_step_sparsity_out(casadi_int i);
int rpr3_platform_apd_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_apd_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_apd_step_SZ_ARG 6
#define rpr3_platform_apd_step_SZ_RES 4
#define rpr3_platform_apd_step_SZ_IW 0
#define rpr3_platform_apd_step_SZ_W 0
int rpr3_platform_apd_minmax_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_apd_minmax_step_checkout(void);
void rpr3_platform_apd_minmax_step_release(int mem);
void rpr3_platform_apd_minmax_step_incref(void);
void rpr3_platform_apd_minmax_step_decref(void);
casadi_int rpr3_platform_apd_minmax_step_n_in(void);
casadi_int rpr3_platform_apd_minmax_step_n_out(void);
casadi_real rpr3_platform_apd_minmax_step_default_in(casadi_int i);
const char* rpr3_platform_apd_minmax_step_name_in(casadi_int i);
const char* rpr3_platform_apd_minmax_step_name_out(casadi_int i);
const casadi_int* rpr3_platform_apd_minmax_step_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_apd_minmax_step_sparsity_out(casadi_int i);
int rpr3_platform_apd_minmax_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_apd_minmax_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_apd_minmax_step_SZ_ARG 6
#define rpr3_platform_apd_minmax_step_SZ_RES 4
#define rpr3_platform_apd_minmax_step_SZ_IW 0
#define rpr3_platform_apd_minmax_step_SZ_W 0
int rpr3_platform_apd_preload_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_apd_preload_step_checkout(void);
void rpr3_platform_apd_preload_step_release(int mem);
void rpr3_platform_apd_preload_step_incref(void);
void rpr3_platform_apd_preload_step_decref(void);
casadi_int rpr3_platform_apd_preload_step_n_in(void);
casadi_int rpr3_platform_apd_preload_step_n_out(void);
casadi_real rpr3_platform_apd_preload_step_default_in(casadi_int i);
const char* rpr3_platform_apd_preload_step_name_in(casadi_int i);
const char* rpr3_platform_apd_preload_step_name_out(casadi_int i);
const casadi_int* rpr3_platform_apd_preload_step_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_apd_preload_step_sparsity_out(casadi_int i);
int rpr3_platform_apd_preload_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_apd_preload_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_apd_preload_step_SZ_ARG 11
#define rpr3_platform_apd_preload_step_SZ_RES 6
#define rpr3_platform_apd_preload_step_SZ_IW 0
#define rpr3_platform_apd_preload_step_SZ_W 82
int rpr3_platform_ctc_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_ctc_step_checkout(void);
void rpr3_platform_ctc_step_release(int mem);
void rpr3_platform_ctc_step_incref(void);
void rpr3_platform_ctc_step_decref(void);
casadi_int rpr3_platform_ctc_step_n_in(void);
casadi_int rpr3_platform_ctc_step_n_out(void);
casadi_real rpr3_platform_ctc_step_default_in(casadi_int i);
const char* rpr3_platform_ctc_step_name_in(casadi_int i);
const char* rpr3_platform_ctc_step_name_out(casadi_int i);
const casadi_int* rpr3_platform_ctc_step_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_ctc_step_sparsity_out(casadi_int i);
int rpr3_platform_ctc_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_ctc_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_ctc_step_SZ_ARG 6
#define rpr3_platform_ctc_step_SZ_RES 4
#define rpr3_platform_ctc_step_SZ_IW 0
#define rpr3_platform_ctc_step_SZ_W 0
int rpr3_platform_ctc_minmax_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_ctc_minmax_step_checkout(void);
void rpr3_platform_ctc_minmax_step_release(int mem);
void rpr3_platform_ctc_minmax_step_incref(void);
void rpr3_platform_ctc_minmax_step_decref(void);
casadi_int rpr3_platform_ctc_minmax_step_n_in(void);
casadi_int rpr3_platform_ctc_minmax_step_n_out(void);
casadi_real rpr3_platform_ctc_minmax_step_default_in(casadi_int i);
const char* rpr3_platform_ctc_minmax_step_name_in(casadi_int i);
const char* rpr3_platform_ctc_minmax_step_name_out(casadi_int i);
const casadi_int* rpr3_platform_ctc_minmax_step_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_ctc_minmax_step_sparsity_out(casadi_int i);
int rpr3_platform_ctc_minmax_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_ctc_minmax_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_ctc_minmax_step_SZ_ARG 6
#define rpr3_platform_ctc_minmax_step_SZ_RES 4
#define rpr3_platform_ctc_minmax_step_SZ_IW 0
#define rpr3_platform_ctc_minmax_step_SZ_W 0
int rpr3_platform_ctc_preload_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_ctc_preload_step_checkout(void);
void rpr3_platform_ctc_preload_step_release(int mem);
void rpr3_platform_ctc_preload_step_incref(void);
void rpr3_platform_ctc_preload_step_decref(void);
casadi_int rpr3_platform_ctc_preload_step_n_in(void);
casadi_int rpr3_platform_ctc_preload_step_n_out(void);
casadi_real rpr3_platform_ctc_preload_step_default_in(casadi_int i);
const char* rpr3_platform_ctc_preload_step_name_in(casadi_int i);
const char* rpr3_platform_ctc_preload_step_name_out(casadi_int i);
const casadi_int* rpr3_platform_ctc_preload_step_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_ctc_preload_step_sparsity_out(casadi_int i);
int rpr3_platform_ctc_preload_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_ctc_preload_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_ctc_preload_step_SZ_ARG 11
#define rpr3_platform_ctc_preload_step_SZ_RES 6
#define rpr3_platform_ctc_preload_step_SZ_IW 0
#define rpr3_platform_ctc_preload_step_SZ_W 82
int rpr3_platform_lqr_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_lqr_step_checkout(void);
void rpr3_platform_lqr_step_release(int mem);
void rpr3_platform_lqr_step_incref(void);
void rpr3_platform_lqr_step_decref(void);
casadi_int rpr3_platform_lqr_step_n_in(void);
casadi_int rpr3_platform_lqr_step_n_out(void);
casadi_real rpr3_platform_lqr_step_default_in(casadi_int i);
const char* rpr3_platform_lqr_step_name_in(casadi_int i);
const char* rpr3_platform_lqr_step_name_out(casadi_int i);
const casadi_int* rpr3_platform_lqr_step_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_lqr_step_sparsity_out(casadi_int i);
int rpr3_platform_lqr_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_lqr_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_lqr_step_SZ_ARG 8
#define rpr3_platform_lqr_step_SZ_RES 4
#define rpr3_platform_lqr_step_SZ_IW 0
#define rpr3_platform_lqr_step_SZ_W 0
int rpr3_platform_lqr_minmax_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_lqr_minmax_step_checkout(void);
void rpr3_platform_lqr_minmax_step_release(int mem);
void rpr3_platform_lqr_minmax_step_incref(void);
void rpr3_platform_lqr_minmax_step_decref(void);
casadi_int rpr3_platform_lqr_minmax_step_n_in(void);
casadi_int rpr3_platform_lqr_minmax_step_n_out(void);
casadi_real rpr3_platform_lqr_minmax_step_default_in(casadi_int i);
const char* rpr3_platform_lqr_minmax_step_name_in(casadi_int i);
const char* rpr3_platform_lqr_minmax_step_name_out(casadi_int i);
const casadi_int* rpr3_platform_lqr_minmax_step_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_lqr_minmax_step_sparsity_out(casadi_int i);
int rpr3_platform_lqr_minmax_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_lqr_minmax_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_lqr_minmax_step_SZ_ARG 8
#define rpr3_platform_lqr_minmax_step_SZ_RES 4
#define rpr3_platform_lqr_minmax_step_SZ_IW 0
#define rpr3_platform_lqr_minmax_step_SZ_W 0
int rpr3_platform_lqr_preload_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_lqr_preload_step_checkout(void);
void rpr3_platform_lqr_preload_step_release(int mem);
void rpr3_platform_lqr_preload_step_incref(void);
void rpr3_platform_lqr_preload_step_decref(void);
casadi_int rpr3_platform_lqr_preload_step_n_in(void);
casadi_int rpr3_platform_lqr_preload_step_n_out(void);
casadi_real rpr3_platform_lqr_preload_step_default_in(casadi_int i);
const char* rpr3_platform_lqr_preload_step_name_in(casadi_int i);
const char* rpr3_platform_lqr_preload_step_name_out(casadi_int i);
const casadi_int* rpr3_platform_lqr_preload_step_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_lqr_preload_step_sparsity_out(casadi_int i);
int rpr3_platform_lqr_preload_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_lqr_preload_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_lqr_preload_step_SZ_ARG 13
#define rpr3_platform_lqr_preload_step_SZ_RES 6
#define rpr3_platform_lqr_preload_step_SZ_IW 0
#define rpr3_platform_lqr_preload_step_SZ_W 82
int rpr3_platform_plant_xedd(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_plant_xedd_checkout(void);
void rpr3_platform_plant_xedd_release(int mem);
void rpr3_platform_plant_xedd_incref(void);
void rpr3_platform_plant_xedd_decref(void);
casadi_int rpr3_platform_plant_xedd_n_in(void);
casadi_int rpr3_platform_plant_xedd_n_out(void);
casadi_real rpr3_platform_plant_xedd_default_in(casadi_int i);
const char* rpr3_platform_plant_xedd_name_in(casadi_int i);
const char* rpr3_platform_plant_xedd_name_out(casadi_int i);
const casadi_int* rpr3_platform_plant_xedd_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_plant_xedd_sparsity_out(casadi_int i);
int rpr3_platform_plant_xedd_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_plant_xedd_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_plant_xedd_SZ_ARG 4
#define rpr3_platform_plant_xedd_SZ_RES 1
#define rpr3_platform_plant_xedd_SZ_IW 0
#define rpr3_platform_plant_xedd_SZ_W 0
int rpr3_platform_plant_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_plant_step_checkout(void);
void rpr3_platform_plant_step_release(int mem);
void rpr3_platform_plant_step_incref(void);
void rpr3_platform_plant_step_decref(void);
casadi_int rpr3_platform_plant_step_n_in(void);
casadi_int rpr3_platform_plant_step_n_out(void);
casadi_real rpr3_platform_plant_step_default_in(casadi_int i);
const char* rpr3_platform_plant_step_name_in(casadi_int i);
const char* rpr3_platform_plant_step_name_out(casadi_int i);
const casadi_int* rpr3_platform_plant_step_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_plant_step_sparsity_out(casadi_int i);
int rpr3_platform_plant_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_plant_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_plant_step_SZ_ARG 4
#define rpr3_platform_plant_step_SZ_RES 1
#define rpr3_platform_plant_step_SZ_IW 0
#define rpr3_platform_plant_step_SZ_W 0
int rpr3_platform_measure(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_measure_checkout(void);
void rpr3_platform_measure_release(int mem);
void rpr3_platform_measure_incref(void);
void rpr3_platform_measure_decref(void);
casadi_int rpr3_platform_measure_n_in(void);
casadi_int rpr3_platform_measure_n_out(void);
casadi_real rpr3_platform_measure_default_in(casadi_int i);
const char* rpr3_platform_measure_name_in(casadi_int i);
const char* rpr3_platform_measure_name_out(casadi_int i);
const casadi_int* rpr3_platform_measure_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_measure_sparsity_out(casadi_int i);
int rpr3_platform_measure_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_measure_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_measure_SZ_ARG 2
#define rpr3_platform_measure_SZ_RES 1
#define rpr3_platform_measure_SZ_IW 0
#define rpr3_platform_measure_SZ_W 0
int rpr3_platform_na_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_na_closed_loop_checkout(void);
void rpr3_platform_na_closed_loop_release(int mem);
void rpr3_platform_na_closed_loop_incref(void);
void rpr3_platform_na_closed_loop_decref(void);
casadi_int rpr3_platform_na_closed_loop_n_in(void);
casadi_int rpr3_platform_na_closed_loop_n_out(void);
casadi_real rpr3_platform_na_closed_loop_default_in(casadi_int i);
const char* rpr3_platform_na_closed_loop_name_in(casadi_int i);
const char* rpr3_platform_na_closed_loop_name_out(casadi_int i);
const casadi_int* rpr3_platform_na_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_na_closed_loop_sparsity_out(casadi_int i);
int rpr3_platform_na_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_na_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_na_closed_loop_SZ_ARG 9
#define rpr3_platform_na_closed_loop_SZ_RES 6
#define rpr3_platform_na_closed_loop_SZ_IW 0
#define rpr3_platform_na_closed_loop_SZ_W 203
int rpr3_platform_na_minmax_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_na_minmax_closed_loop_checkout(void);
void rpr3_platform_na_minmax_closed_loop_release(int mem);
void rpr3_platform_na_minmax_closed_loop_incref(void);
void rpr3_platform_na_minmax_closed_loop_decref(void);
casadi_int rpr3_platform_na_minmax_closed_loop_n_in(void);
casadi_int rpr3_platform_na_minmax_closed_loop_n_out(void);
casadi_real rpr3_platform_na_minmax_closed_loop_default_in(casadi_int i);
const char* rpr3_platform_na_minmax_closed_loop_name_in(casadi_int i);
const char* rpr3_platform_na_minmax_closed_loop_name_out(casadi_int i);
const casadi_int* rpr3_platform_na_minmax_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_na_minmax_closed_loop_sparsity_out(casadi_int i);
int rpr3_platform_na_minmax_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_na_minmax_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_na_minmax_closed_loop_SZ_ARG 9
#define rpr3_platform_na_minmax_closed_loop_SZ_RES 6
#define rpr3_platform_na_minmax_closed_loop_SZ_IW 0
#define rpr3_platform_na_minmax_closed_loop_SZ_W 203
int rpr3_platform_na_preload_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_na_preload_closed_loop_checkout(void);
void rpr3_platform_na_preload_closed_loop_release(int mem);
void rpr3_platform_na_preload_closed_loop_incref(void);
void rpr3_platform_na_preload_closed_loop_decref(void);
casadi_int rpr3_platform_na_preload_closed_loop_n_in(void);
casadi_int rpr3_platform_na_preload_closed_loop_n_out(void);
casadi_real rpr3_platform_na_preload_closed_loop_default_in(casadi_int i);
const char* rpr3_platform_na_preload_closed_loop_name_in(casadi_int i);
const char* rpr3_platform_na_preload_closed_loop_name_out(casadi_int i);
const casadi_int* rpr3_platform_na_preload_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_na_preload_closed_loop_sparsity_out(casadi_int i);
int rpr3_platform_na_preload_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_na_preload_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_na_preload_closed_loop_SZ_ARG 14
#define rpr3_platform_na_preload_closed_loop_SZ_RES 8
#define rpr3_platform_na_preload_closed_loop_SZ_IW 0
#define rpr3_platform_na_preload_closed_loop_SZ_W 265
int rpr3_platform_na_proj_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_na_proj_closed_loop_checkout(void);
void rpr3_platform_na_proj_closed_loop_release(int mem);
void rpr3_platform_na_proj_closed_loop_incref(void);
void rpr3_platform_na_proj_closed_loop_decref(void);
casadi_int rpr3_platform_na_proj_closed_loop_n_in(void);
casadi_int rpr3_platform_na_proj_closed_loop_n_out(void);
casadi_real rpr3_platform_na_proj_closed_loop_default_in(casadi_int i);
const char* rpr3_platform_na_proj_closed_loop_name_in(casadi_int i);
const char* rpr3_platform_na_proj_closed_loop_name_out(casadi_int i);
const casadi_int* rpr3_platform_na_proj_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_na_proj_closed_loop_sparsity_out(casadi_int i);
int rpr3_platform_na_proj_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_na_proj_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_na_proj_closed_loop_SZ_ARG 9
#define rpr3_platform_na_proj_closed_loop_SZ_RES 6
#define rpr3_platform_na_proj_closed_loop_SZ_IW 0
#define rpr3_platform_na_proj_closed_loop_SZ_W 203
int rpr3_platform_na_proj_minmax_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_na_proj_minmax_closed_loop_checkout(void);
void rpr3_platform_na_proj_minmax_closed_loop_release(int mem);
void rpr3_platform_na_proj_minmax_closed_loop_incref(void);
void rpr3_platform_na_proj_minmax_closed_loop_decref(void);
casadi_int rpr3_platform_na_proj_minmax_closed_loop_n_in(void);
casadi_int rpr3_platform_na_proj_minmax_closed_loop_n_out(void);
casadi_real rpr3_platform_na_proj_minmax_closed_loop_default_in(casadi_int i);
const char* rpr3_platform_na_proj_minmax_closed_loop_name_in(casadi_int i);
const char* rpr3_platform_na_proj_minmax_closed_loop_name_out(casadi_int i);
const casadi_int* rpr3_platform_na_proj_minmax_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_na_proj_minmax_closed_loop_sparsity_out(casadi_int i);
int rpr3_platform_na_proj_minmax_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_na_proj_minmax_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_na_proj_minmax_closed_loop_SZ_ARG 9
#define rpr3_platform_na_proj_minmax_closed_loop_SZ_RES 6
#define rpr3_platform_na_proj_minmax_closed_loop_SZ_IW 0
#define rpr3_platform_na_proj_minmax_closed_loop_SZ_W 203
int rpr3_platform_na_proj_preload_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_na_proj_preload_closed_loop_checkout(void);
void rpr3_platform_na_proj_preload_closed_loop_release(int mem);
void rpr3_platform_na_proj_preload_closed_loop_incref(void);
void rpr3_platform_na_proj_preload_closed_loop_decref(void);
casadi_int rpr3_platform_na_proj_preload_closed_loop_n_in(void);
casadi_int rpr3_platform_na_proj_preload_closed_loop_n_out(void);
casadi_real rpr3_platform_na_proj_preload_closed_loop_default_in(casadi_int i);
const char* rpr3_platform_na_proj_preload_closed_loop_name_in(casadi_int i);
const char* rpr3_platform_na_proj_preload_closed_loop_name_out(casadi_int i);
const casadi_int* rpr3_platform_na_proj_preload_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_na_proj_preload_closed_loop_sparsity_out(casadi_int i);
int rpr3_platform_na_proj_preload_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_na_proj_preload_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_na_proj_preload_closed_loop_SZ_ARG 14
#define rpr3_platform_na_proj_preload_closed_loop_SZ_RES 8
#define rpr3_platform_na_proj_preload_closed_loop_SZ_IW 0
#define rpr3_platform_na_proj_preload_closed_loop_SZ_W 265
int rpr3_platform_apd_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_apd_closed_loop_checkout(void);
void rpr3_platform_apd_closed_loop_release(int mem);
void rpr3_platform_apd_closed_loop_incref(void);
void rpr3_platform_apd_closed_loop_decref(void);
casadi_int rpr3_platform_apd_closed_loop_n_in(void);
casadi_int rpr3_platform_apd_closed_loop_n_out(void);
casadi_real rpr3_platform_apd_closed_loop_default_in(casadi_int i);
const char* rpr3_platform_apd_closed_loop_name_in(casadi_int i);
const char* rpr3_platform_apd_closed_loop_name_out(casadi_int i);
const casadi_int* rpr3_platform_apd_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_apd_closed_loop_sparsity_out(casadi_int i);
int rpr3_platform_apd_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_apd_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_apd_closed_loop_SZ_ARG 9
#define rpr3_platform_apd_closed_loop_SZ_RES 6
#define rpr3_platform_apd_closed_loop_SZ_IW 0
#define rpr3_platform_apd_closed_loop_SZ_W 203
int rpr3_platform_apd_minmax_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_apd_minmax_closed_loop_checkout(void);
void rpr3_platform_apd_minmax_closed_loop_release(int mem);
void rpr3_platform_apd_minmax_closed_loop_incref(void);
void rpr3_platform_apd_minmax_closed_loop_decref(void);
casadi_int rpr3_platform_apd_minmax_closed_loop_n_in(void);
casadi_int rpr3_platform_apd_minmax_closed_loop_n_out(void);
casadi_real rpr3_platform_apd_minmax_closed_loop_default_in(casadi_int i);
const char* rpr3_platform_apd_minmax_closed_loop_name_in(casadi_int i);
const char* rpr3_platform_apd_minmax_closed_loop_name_out(casadi_int i);
const casadi_int* rpr3_platform_apd_minmax_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_apd_minmax_closed_loop_sparsity_out(casadi_int i);
int rpr3_platform_apd_minmax_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_apd_minmax_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_apd_minmax_closed_loop_SZ_ARG 9
#define rpr3_platform_apd_minmax_closed_loop_SZ_RES 6
#define rpr3_platform_apd_minmax_closed_loop_SZ_IW 0
#define rpr3_platform_apd_minmax_closed_loop_SZ_W 203
int rpr3_platform_apd_preload_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_apd_preload_closed_loop_checkout(void);
void rpr3_platform_apd_preload_closed_loop_release(int mem);
void rpr3_platform_apd_preload_closed_loop_incref(void);
void rpr3_platform_apd_preload_closed_loop_decref(void);
casadi_int rpr3_platform_apd_preload_closed_loop_n_in(void);
casadi_int rpr3_platform_apd_preload_closed_loop_n_out(void);
casadi_real rpr3_platform_apd_preload_closed_loop_default_in(casadi_int i);
const char* rpr3_platform_apd_preload_closed_loop_name_in(casadi_int i);
const char* rpr3_platform_apd_preload_closed_loop_name_out(casadi_int i);
const casadi_int* rpr3_platform_apd_preload_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_apd_preload_closed_loop_sparsity_out(casadi_int i);
int rpr3_platform_apd_preload_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_apd_preload_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_apd_preload_closed_loop_SZ_ARG 14
#define rpr3_platform_apd_preload_closed_loop_SZ_RES 8
#define rpr3_platform_apd_preload_closed_loop_SZ_IW 0
#define rpr3_platform_apd_preload_closed_loop_SZ_W 231
int rpr3_platform_ctc_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_ctc_closed_loop_checkout(void);
void rpr3_platform_ctc_closed_loop_release(int mem);
void rpr3_platform_ctc_closed_loop_incref(void);
void rpr3_platform_ctc_closed_loop_decref(void);
casadi_int rpr3_platform_ctc_closed_loop_n_in(void);
casadi_int rpr3_platform_ctc_closed_loop_n_out(void);
casadi_real rpr3_platform_ctc_closed_loop_default_in(casadi_int i);
const char* rpr3_platform_ctc_closed_loop_name_in(casadi_int i);
const char* rpr3_platform_ctc_closed_loop_name_out(casadi_int i);
const casadi_int* rpr3_platform_ctc_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_ctc_closed_loop_sparsity_out(casadi_int i);
int rpr3_platform_ctc_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_ctc_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_ctc_closed_loop_SZ_ARG 9
#define rpr3_platform_ctc_closed_loop_SZ_RES 6
#define rpr3_platform_ctc_closed_loop_SZ_IW 0
#define rpr3_platform_ctc_closed_loop_SZ_W 203
int rpr3_platform_ctc_minmax_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_ctc_minmax_closed_loop_checkout(void);
void rpr3_platform_ctc_minmax_closed_loop_release(int mem);
void rpr3_platform_ctc_minmax_closed_loop_incref(void);
void rpr3_platform_ctc_minmax_closed_loop_decref(void);
casadi_int rpr3_platform_ctc_minmax_closed_loop_n_in(void);
casadi_int rpr3_platform_ctc_minmax_closed_loop_n_out(void);
casadi_real rpr3_platform_ctc_minmax_closed_loop_default_in(casadi_int i);
const char* rpr3_platform_ctc_minmax_closed_loop_name_in(casadi_int i);
const char* rpr3_platform_ctc_minmax_closed_loop_name_out(casadi_int i);
const casadi_int* rpr3_platform_ctc_minmax_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_ctc_minmax_closed_loop_sparsity_out(casadi_int i);
int rpr3_platform_ctc_minmax_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_ctc_minmax_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_ctc_minmax_closed_loop_SZ_ARG 9
#define rpr3_platform_ctc_minmax_closed_loop_SZ_RES 6
#define rpr3_platform_ctc_minmax_closed_loop_SZ_IW 0
#define rpr3_platform_ctc_minmax_closed_loop_SZ_W 203
int rpr3_platform_ctc_preload_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_ctc_preload_closed_loop_checkout(void);
void rpr3_platform_ctc_preload_closed_loop_release(int mem);
void rpr3_platform_ctc_preload_closed_loop_incref(void);
void rpr3_platform_ctc_preload_closed_loop_decref(void);
casadi_int rpr3_platform_ctc_preload_closed_loop_n_in(void);
casadi_int rpr3_platform_ctc_preload_closed_loop_n_out(void);
casadi_real rpr3_platform_ctc_preload_closed_loop_default_in(casadi_int i);
const char* rpr3_platform_ctc_preload_closed_loop_name_in(casadi_int i);
const char* rpr3_platform_ctc_preload_closed_loop_name_out(casadi_int i);
const casadi_int* rpr3_platform_ctc_preload_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_ctc_preload_closed_loop_sparsity_out(casadi_int i);
int rpr3_platform_ctc_preload_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_ctc_preload_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_ctc_preload_closed_loop_SZ_ARG 14
#define rpr3_platform_ctc_preload_closed_loop_SZ_RES 8
#define rpr3_platform_ctc_preload_closed_loop_SZ_IW 0
#define rpr3_platform_ctc_preload_closed_loop_SZ_W 233
int rpr3_platform_lqr_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_lqr_closed_loop_checkout(void);
void rpr3_platform_lqr_closed_loop_release(int mem);
void rpr3_platform_lqr_closed_loop_incref(void);
void rpr3_platform_lqr_closed_loop_decref(void);
casadi_int rpr3_platform_lqr_closed_loop_n_in(void);
casadi_int rpr3_platform_lqr_closed_loop_n_out(void);
casadi_real rpr3_platform_lqr_closed_loop_default_in(casadi_int i);
const char* rpr3_platform_lqr_closed_loop_name_in(casadi_int i);
const char* rpr3_platform_lqr_closed_loop_name_out(casadi_int i);
const casadi_int* rpr3_platform_lqr_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_lqr_closed_loop_sparsity_out(casadi_int i);
int rpr3_platform_lqr_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_lqr_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_lqr_closed_loop_SZ_ARG 11
#define rpr3_platform_lqr_closed_loop_SZ_RES 6
#define rpr3_platform_lqr_closed_loop_SZ_IW 0
#define rpr3_platform_lqr_closed_loop_SZ_W 203
int rpr3_platform_lqr_minmax_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_lqr_minmax_closed_loop_checkout(void);
void rpr3_platform_lqr_minmax_closed_loop_release(int mem);
void rpr3_platform_lqr_minmax_closed_loop_incref(void);
void rpr3_platform_lqr_minmax_closed_loop_decref(void);
casadi_int rpr3_platform_lqr_minmax_closed_loop_n_in(void);
casadi_int rpr3_platform_lqr_minmax_closed_loop_n_out(void);
casadi_real rpr3_platform_lqr_minmax_closed_loop_default_in(casadi_int i);
const char* rpr3_platform_lqr_minmax_closed_loop_name_in(casadi_int i);
const char* rpr3_platform_lqr_minmax_closed_loop_name_out(casadi_int i);
const casadi_int* rpr3_platform_lqr_minmax_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_lqr_minmax_closed_loop_sparsity_out(casadi_int i);
int rpr3_platform_lqr_minmax_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_lqr_minmax_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_lqr_minmax_closed_loop_SZ_ARG 11
#define rpr3_platform_lqr_minmax_closed_loop_SZ_RES 6
#define rpr3_platform_lqr_minmax_closed_loop_SZ_IW 0
#define rpr3_platform_lqr_minmax_closed_loop_SZ_W 203
int rpr3_platform_lqr_preload_closed_loop(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_lqr_preload_closed_loop_checkout(void);
void rpr3_platform_lqr_preload_closed_loop_release(int mem);
void rpr3_platform_lqr_preload_closed_loop_incref(void);
void rpr3_platform_lqr_preload_closed_loop_decref(void);
casadi_int rpr3_platform_lqr_preload_closed_loop_n_in(void);
casadi_int rpr3_platform_lqr_preload_closed_loop_n_out(void);
casadi_real rpr3_platform_lqr_preload_closed_loop_default_in(casadi_int i);
const char* rpr3_platform_lqr_preload_closed_loop_name_in(casadi_int i);
const char* rpr3_platform_lqr_preload_closed_loop_name_out(casadi_int i);
const casadi_int* rpr3_platform_lqr_preload_closed_loop_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_lqr_preload_closed_loop_sparsity_out(casadi_int i);
int rpr3_platform_lqr_preload_closed_loop_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_lqr_preload_closed_loop_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_lqr_preload_closed_loop_SZ_ARG 16
#define rpr3_platform_lqr_preload_closed_loop_SZ_RES 8
#define rpr3_platform_lqr_preload_closed_loop_SZ_IW 0
#define rpr3_platform_lqr_preload_closed_loop_SZ_W 203
int rpr3_platform_path_coefficients(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_path_coefficients_checkout(void);
void rpr3_platform_path_coefficients_release(int mem);
void rpr3_platform_path_coefficients_incref(void);
void rpr3_platform_path_coefficients_decref(void);
casadi_int rpr3_platform_path_coefficients_n_in(void);
casadi_int rpr3_platform_path_coefficients_n_out(void);
casadi_real rpr3_platform_path_coefficients_default_in(casadi_int i);
const char* rpr3_platform_path_coefficients_name_in(casadi_int i);
const char* rpr3_platform_path_coefficients_name_out(casadi_int i);
const casadi_int* rpr3_platform_path_coefficients_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_path_coefficients_sparsity_out(casadi_int i);
int rpr3_platform_path_coefficients_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_path_coefficients_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_path_coefficients_SZ_ARG 5
#define rpr3_platform_path_coefficients_SZ_RES 9
#define rpr3_platform_path_coefficients_SZ_IW 0
#define rpr3_platform_path_coefficients_SZ_W 0
int rpr3_platform_path_mvc(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_path_mvc_checkout(void);
void rpr3_platform_path_mvc_release(int mem);
void rpr3_platform_path_mvc_incref(void);
void rpr3_platform_path_mvc_decref(void);
casadi_int rpr3_platform_path_mvc_n_in(void);
casadi_int rpr3_platform_path_mvc_n_out(void);
casadi_real rpr3_platform_path_mvc_default_in(casadi_int i);
const char* rpr3_platform_path_mvc_name_in(casadi_int i);
const char* rpr3_platform_path_mvc_name_out(casadi_int i);
const casadi_int* rpr3_platform_path_mvc_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_path_mvc_sparsity_out(casadi_int i);
int rpr3_platform_path_mvc_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_path_mvc_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_path_mvc_SZ_ARG 2
#define rpr3_platform_path_mvc_SZ_RES 1
#define rpr3_platform_path_mvc_SZ_IW 0
#define rpr3_platform_path_mvc_SZ_W 0
int rpr3_platform_path_backward(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_path_backward_checkout(void);
void rpr3_platform_path_backward_release(int mem);
void rpr3_platform_path_backward_incref(void);
void rpr3_platform_path_backward_decref(void);
casadi_int rpr3_platform_path_backward_n_in(void);
casadi_int rpr3_platform_path_backward_n_out(void);
casadi_real rpr3_platform_path_backward_default_in(casadi_int i);
const char* rpr3_platform_path_backward_name_in(casadi_int i);
const char* rpr3_platform_path_backward_name_out(casadi_int i);
const casadi_int* rpr3_platform_path_backward_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_path_backward_sparsity_out(casadi_int i);
int rpr3_platform_path_backward_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_path_backward_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_path_backward_SZ_ARG 22
#define rpr3_platform_path_backward_SZ_RES 9
#define rpr3_platform_path_backward_SZ_IW 0
#define rpr3_platform_path_backward_SZ_W 366
int rpr3_platform_path_forward(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_path_forward_checkout(void);
void rpr3_platform_path_forward_release(int mem);
void rpr3_platform_path_forward_incref(void);
void rpr3_platform_path_forward_decref(void);
casadi_int rpr3_platform_path_forward_n_in(void);
casadi_int rpr3_platform_path_forward_n_out(void);
casadi_real rpr3_platform_path_forward_default_in(casadi_int i);
const char* rpr3_platform_path_forward_name_in(casadi_int i);
const char* rpr3_platform_path_forward_name_out(casadi_int i);
const casadi_int* rpr3_platform_path_forward_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_path_forward_sparsity_out(casadi_int i);
int rpr3_platform_path_forward_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_path_forward_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_path_forward_SZ_ARG 10
#define rpr3_platform_path_forward_SZ_RES 6
#define rpr3_platform_path_forward_SZ_IW 0
#define rpr3_platform_path_forward_SZ_W 103
int rpr3_platform_path_torques(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_path_torques_checkout(void);
void rpr3_platform_path_torques_release(int mem);
void rpr3_platform_path_torques_incref(void);
void rpr3_platform_path_torques_decref(void);
casadi_int rpr3_platform_path_torques_n_in(void);
casadi_int rpr3_platform_path_torques_n_out(void);
casadi_real rpr3_platform_path_torques_default_in(casadi_int i);
const char* rpr3_platform_path_torques_name_in(casadi_int i);
const char* rpr3_platform_path_torques_name_out(casadi_int i);
const casadi_int* rpr3_platform_path_torques_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_path_torques_sparsity_out(casadi_int i);
int rpr3_platform_path_torques_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_path_torques_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_path_torques_SZ_ARG 5
#define rpr3_platform_path_torques_SZ_RES 4
#define rpr3_platform_path_torques_SZ_IW 0
#define rpr3_platform_path_torques_SZ_W 0
int rpr3_platform_forward_dynamics_jacobians(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_forward_dynamics_jacobians_checkout(void);
void rpr3_platform_forward_dynamics_jacobians_release(int mem);
void rpr3_platform_forward_dynamics_jacobians_incref(void);
void rpr3_platform_forward_dynamics_jacobians_decref(void);
casadi_int rpr3_platform_forward_dynamics_jacobians_n_in(void);
casadi_int rpr3_platform_forward_dynamics_jacobians_n_out(void);
casadi_real rpr3_platform_forward_dynamics_jacobians_default_in(casadi_int i);
const char* rpr3_platform_forward_dynamics_jacobians_name_in(casadi_int i);
const char* rpr3_platform_forward_dynamics_jacobians_name_out(casadi_int i);
const casadi_int* rpr3_platform_forward_dynamics_jacobians_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_forward_dynamics_jacobians_sparsity_out(casadi_int i);
int rpr3_platform_forward_dynamics_jacobians_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_forward_dynamics_jacobians_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_forward_dynamics_jacobians_SZ_ARG 4
#define rpr3_platform_forward_dynamics_jacobians_SZ_RES 6
#define rpr3_platform_forward_dynamics_jacobians_SZ_IW 0
#define rpr3_platform_forward_dynamics_jacobians_SZ_W 0
int rpr3_platform_inverse_dynamics(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_inverse_dynamics_checkout(void);
void rpr3_platform_inverse_dynamics_release(int mem);
void rpr3_platform_inverse_dynamics_incref(void);
void rpr3_platform_inverse_dynamics_decref(void);
casadi_int rpr3_platform_inverse_dynamics_n_in(void);
casadi_int rpr3_platform_inverse_dynamics_n_out(void);
casadi_real rpr3_platform_inverse_dynamics_default_in(casadi_int i);
const char* rpr3_platform_inverse_dynamics_name_in(casadi_int i);
const char* rpr3_platform_inverse_dynamics_name_out(casadi_int i);
const casadi_int* rpr3_platform_inverse_dynamics_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_inverse_dynamics_sparsity_out(casadi_int i);
int rpr3_platform_inverse_dynamics_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_inverse_dynamics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_inverse_dynamics_SZ_ARG 4
#define rpr3_platform_inverse_dynamics_SZ_RES 2
#define rpr3_platform_inverse_dynamics_SZ_IW 0
#define rpr3_platform_inverse_dynamics_SZ_W 0
int rpr3_platform_inverse_dynamics_jacobians(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_inverse_dynamics_jacobians_checkout(void);
void rpr3_platform_inverse_dynamics_jacobians_release(int mem);
void rpr3_platform_inverse_dynamics_jacobians_incref(void);
void rpr3_platform_inverse_dynamics_jacobians_decref(void);
casadi_int rpr3_platform_inverse_dynamics_jacobians_n_in(void);
casadi_int rpr3_platform_inverse_dynamics_jacobians_n_out(void);
casadi_real rpr3_platform_inverse_dynamics_jacobians_default_in(casadi_int i);
const char* rpr3_platform_inverse_dynamics_jacobians_name_in(casadi_int i);
const char* rpr3_platform_inverse_dynamics_jacobians_name_out(casadi_int i);
const casadi_int* rpr3_platform_inverse_dynamics_jacobians_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_inverse_dynamics_jacobians_sparsity_out(casadi_int i);
int rpr3_platform_inverse_dynamics_jacobians_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_inverse_dynamics_jacobians_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_inverse_dynamics_jacobians_SZ_ARG 4
#define rpr3_platform_inverse_dynamics_jacobians_SZ_RES 4
#define rpr3_platform_inverse_dynamics_jacobians_SZ_IW 0
#define rpr3_platform_inverse_dynamics_jacobians_SZ_W 0
int rpr3_platform_sampled_step(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_sampled_step_checkout(void);
void rpr3_platform_sampled_step_release(int mem);
void rpr3_platform_sampled_step_incref(void);
void rpr3_platform_sampled_step_decref(void);
casadi_int rpr3_platform_sampled_step_n_in(void);
casadi_int rpr3_platform_sampled_step_n_out(void);
casadi_real rpr3_platform_sampled_step_default_in(casadi_int i);
const char* rpr3_platform_sampled_step_name_in(casadi_int i);
const char* rpr3_platform_sampled_step_name_out(casadi_int i);
const casadi_int* rpr3_platform_sampled_step_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_sampled_step_sparsity_out(casadi_int i);
int rpr3_platform_sampled_step_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_sampled_step_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_sampled_step_SZ_ARG 8
#define rpr3_platform_sampled_step_SZ_RES 4
#define rpr3_platform_sampled_step_SZ_IW 0
#define rpr3_platform_sampled_step_SZ_W 133
int rpr3_platform_sampled_step_jacobians(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_sampled_step_jacobians_checkout(void);
void rpr3_platform_sampled_step_jacobians_release(int mem);
void rpr3_platform_sampled_step_jacobians_incref(void);
void rpr3_platform_sampled_step_jacobians_decref(void);
casadi_int rpr3_platform_sampled_step_jacobians_n_in(void);
casadi_int rpr3_platform_sampled_step_jacobians_n_out(void);
casadi_real rpr3_platform_sampled_step_jacobians_default_in(casadi_int i);
const char* rpr3_platform_sampled_step_jacobians_name_in(casadi_int i);
const char* rpr3_platform_sampled_step_jacobians_name_out(casadi_int i);
const casadi_int* rpr3_platform_sampled_step_jacobians_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_sampled_step_jacobians_sparsity_out(casadi_int i);
int rpr3_platform_sampled_step_jacobians_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_sampled_step_jacobians_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_sampled_step_jacobians_SZ_ARG 8
#define rpr3_platform_sampled_step_jacobians_SZ_RES 10
#define rpr3_platform_sampled_step_jacobians_SZ_IW 10
#define rpr3_platform_sampled_step_jacobians_SZ_W 3180
int rpr3_platform_Ge(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_Ge_checkout(void);
void rpr3_platform_Ge_release(int mem);
void rpr3_platform_Ge_incref(void);
void rpr3_platform_Ge_decref(void);
casadi_int rpr3_platform_Ge_n_in(void);
casadi_int rpr3_platform_Ge_n_out(void);
casadi_real rpr3_platform_Ge_default_in(casadi_int i);
const char* rpr3_platform_Ge_name_in(casadi_int i);
const char* rpr3_platform_Ge_name_out(casadi_int i);
const casadi_int* rpr3_platform_Ge_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_Ge_sparsity_out(casadi_int i);
int rpr3_platform_Ge_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_Ge_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_Ge_SZ_ARG 2
#define rpr3_platform_Ge_SZ_RES 2
#define rpr3_platform_Ge_SZ_IW 0
#define rpr3_platform_Ge_SZ_W 0
int rpr3_platform_kinetic_energy(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_kinetic_energy_checkout(void);
void rpr3_platform_kinetic_energy_release(int mem);
void rpr3_platform_kinetic_energy_incref(void);
void rpr3_platform_kinetic_energy_decref(void);
casadi_int rpr3_platform_kinetic_energy_n_in(void);
casadi_int rpr3_platform_kinetic_energy_n_out(void);
casadi_real rpr3_platform_kinetic_energy_default_in(casadi_int i);
const char* rpr3_platform_kinetic_energy_name_in(casadi_int i);
const char* rpr3_platform_kinetic_energy_name_out(casadi_int i);
const casadi_int* rpr3_platform_kinetic_energy_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_kinetic_energy_sparsity_out(casadi_int i);
int rpr3_platform_kinetic_energy_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_kinetic_energy_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_kinetic_energy_SZ_ARG 3
#define rpr3_platform_kinetic_energy_SZ_RES 1
#define rpr3_platform_kinetic_energy_SZ_IW 0
#define rpr3_platform_kinetic_energy_SZ_W 0
int rpr3_platform_potential_energy(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem);
int rpr3_platform_potential_energy_checkout(void);
void rpr3_platform_potential_energy_release(int mem);
void rpr3_platform_potential_energy_incref(void);
void rpr3_platform_potential_energy_decref(void);
casadi_int rpr3_platform_potential_energy_n_in(void);
casadi_int rpr3_platform_potential_energy_n_out(void);
casadi_real rpr3_platform_potential_energy_default_in(casadi_int i);
const char* rpr3_platform_potential_energy_name_in(casadi_int i);
const char* rpr3_platform_potential_energy_name_out(casadi_int i);
const casadi_int* rpr3_platform_potential_energy_sparsity_in(casadi_int i);
const casadi_int* rpr3_platform_potential_energy_sparsity_out(casadi_int i);
int rpr3_platform_potential_energy_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
int rpr3_platform_potential_energy_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w);
#define rpr3_platform_potential_energy_SZ_ARG 2
#define rpr3_platform_potential_energy_SZ_RES 1
#define rpr3_platform_potential_energy_SZ_IW 0
#define rpr3_platform_potential_energy_SZ_W 0
void rpr3_platform_casadi_version(int* major, int* minor, int* patch);
int rpr3_platform_casadi_int_size(void);
int rpr3_platform_casadi_real_size(void);
#ifdef __cplusplus
} /* extern "C" */
#endif
