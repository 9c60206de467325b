/* SPDX-License-Identifier: BSD-3-Clause */
/* python/mtt/_core.c - mtt._core, the CPython extension behind the mtt package:
 * one mtt_tracker per _core.Tracker object, the parameter table (mtt_params_info),
 * and plain tuples / bytes in and out (no numpy C API: python/mtt/tracker.py
 * wraps them in numpy arrays, so the build needs no numpy headers).
 *
 * Every method returns the mtt_status as an int where the library returns one;
 * python/mtt/tracker.py turns it into the exception and the message.  Argument
 * checks that Python cannot leave to the library (sizes of the buffers) raise
 * here.  The library leaves everything unchanged on error (include/mtt/mtt.h),
 * and so does every method of this module.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include <math.h>
#include <string.h>

#include "mtt/mtt.h"

#ifdef MTT_REAL_DOUBLE
#define REAL_NAME "double"
#else
#define REAL_NAME "float"
#endif

typedef struct {
    PyObject_HEAD
    mtt_params par;     /* the parameters being set, then the tracker's */
    mtt_tracker *trk;   /* NULL until init() succeeds */
} CoreTracker;

/* A double as mtt_real: 0 when it is not finite or does not fit. */
static int to_real(double v, mtt_real *out)
{
    if (!isfinite(v) || fabs(v) > (double)MTT_REAL_MAX)
        return 0;
    *out = (mtt_real)v;
    return 1;
}

/* ---- module functions ---------------------------------------------------- */

static PyObject *info_tuple(const mtt_param_info *in)
{
    PyObject *names, *row;
    uint8_t k;

    names = PyTuple_New(in->n_names);
    if (names == NULL)
        return NULL;
    for (k = 0; k < in->n_names; ++k) {
        PyObject *s = PyUnicode_FromString(in->names[k]);
        if (s == NULL) {
            Py_DECREF(names);
            return NULL;
        }
        PyTuple_SET_ITEM(names, k, s);
    }
    row = Py_BuildValue("(siiddiiNzsi)", in->key, (int)in->type, (int)in->count, in->lo, in->hi,
                        (int)in->lo_open, (int)in->hi_open, names, in->cross, in->text,
                        (int)in->per_model);
    return row;
}

static PyObject *core_params_info(PyObject *self, PyObject *unused)
{
    const mtt_param_info *in;
    PyObject *list = PyList_New(0);
    size_t i;
    (void)self;
    (void)unused;
    if (list == NULL)
        return NULL;
    for (i = 0; mtt_params_info(i, &in) == MTT_OK; ++i) {
        PyObject *row = info_tuple(in);
        if (row == NULL || PyList_Append(list, row) != 0) {
            Py_XDECREF(row);
            Py_DECREF(list);
            return NULL;
        }
        Py_DECREF(row);
    }
    return list;
}

static PyObject *core_status_text(PyObject *self, PyObject *args)
{
    int s;
    const char *text = "unknown status";
    (void)self;
    if (!PyArg_ParseTuple(args, "i", &s))
        return NULL;
    if (mtt_status_text((mtt_status)s, &text) != MTT_OK)
        text = "unknown status";
    return PyUnicode_FromString(text);
}

static PyObject *matrix_tuple(const mtt_real *P, Py_ssize_t n)
{
    PyObject *t = PyTuple_New(n);
    Py_ssize_t i;
    if (t == NULL)
        return NULL;
    for (i = 0; i < n; ++i) {
        PyObject *f = PyFloat_FromDouble((double)P[i]);
        if (f == NULL) {
            Py_DECREF(t);
            return NULL;
        }
        PyTuple_SET_ITEM(t, i, f);
    }
    return t;
}

/* two_point_cov(sx, sy, dt) -> (status, 16 values row-major or None) */
static PyObject *core_two_point_cov(PyObject *self, PyObject *args)
{
    double sx, sy, dt;
    mtt_real rx, ry, rdt, P[4][4];
    mtt_status st;
    (void)self;
    if (!PyArg_ParseTuple(args, "ddd", &sx, &sy, &dt))
        return NULL;
    if (!to_real(sx, &rx) || !to_real(sy, &ry) || !to_real(dt, &rdt))
        return Py_BuildValue("(iO)", (int)MTT_ERR_VALUE, Py_None);
    st = mtt_init_two_point_cov(rx, ry, rdt, P);
    if (st != MTT_OK)
        return Py_BuildValue("(iO)", (int)st, Py_None);
    return Py_BuildValue("(iN)", (int)st, matrix_tuple(&P[0][0], 16));
}

/* ---- Tracker ------------------------------------------------------------- */

static int tracker_init(CoreTracker *self, PyObject *args, PyObject *kwds)
{
    static char *kwlist[] = {NULL};
    if (!PyArg_ParseTupleAndKeywords(args, kwds, "", kwlist))
        return -1;
    if (mtt_params_default(&self->par) != MTT_OK) {
        PyErr_SetString(PyExc_RuntimeError, "mtt_params_default failed");
        return -1;
    }
    return 0;
}

static void tracker_dealloc(CoreTracker *self)
{
    PyMem_Free(self->trk);
    Py_TYPE(self)->tp_free((PyObject *)self);
}

/* A tuple or list of numbers into v[0..n). */
static int numbers(PyObject *seq, double *v, Py_ssize_t n, const char *what)
{
    PyObject *fast = PySequence_Fast(seq, what);
    Py_ssize_t i;
    if (fast == NULL)
        return 0;
    if (PySequence_Fast_GET_SIZE(fast) != n) {
        PyErr_Format(PyExc_ValueError, "%s: expected %zd values", what, n);
        Py_DECREF(fast);
        return 0;
    }
    for (i = 0; i < n; ++i) {
        v[i] = PyFloat_AsDouble(PySequence_Fast_GET_ITEM(fast, i));
        if (v[i] == -1.0 && PyErr_Occurred()) {
            Py_DECREF(fast);
            return 0;
        }
    }
    Py_DECREF(fast);
    return 1;
}

/* Values of one key: 16 (a 4x4 covariance), imm_transition's
 * MTT_MAX_MODELS^2, imm_models' 1 + MTT_PARAM_MODEL_VALUES MTT_MAX_MODELS. */
#define PARAM_VALUES_MAX (16 + MTT_MAX_MODELS * MTT_MAX_MODELS + MTT_PARAM_MODEL_VALUES * MTT_MAX_MODELS)

/* set_param(key, values) -> status of mtt_params_set (before init only) */
static PyObject *tracker_set_param(CoreTracker *self, PyObject *args)
{
    const char *key;
    PyObject *seq;
    double v[PARAM_VALUES_MAX];
    Py_ssize_t n;
    if (!PyArg_ParseTuple(args, "sO", &key, &seq))
        return NULL;
    if (self->trk != NULL) {
        PyErr_SetString(PyExc_RuntimeError, "the tracker is initialised: parameters are fixed");
        return NULL;
    }
    n = PySequence_Size(seq);
    if (n < 0)
        return NULL;
    if (n < 1 || n > PARAM_VALUES_MAX)
        return PyLong_FromLong((long)MTT_ERR_RANGE);
    if (!numbers(seq, v, n, "set_param"))
        return NULL;
    return PyLong_FromLong((long)mtt_params_set(&self->par, key, v, (size_t)n));
}

/* get_param(key, n) -> (status, tuple of n values or None) */
static PyObject *tracker_get_param(CoreTracker *self, PyObject *args)
{
    const char *key;
    Py_ssize_t n, i;
    double v[PARAM_VALUES_MAX];
    mtt_status st;
    PyObject *t;
    if (!PyArg_ParseTuple(args, "sn", &key, &n))
        return NULL;
    if (n < 1 || n > PARAM_VALUES_MAX)
        return Py_BuildValue("(iO)", (int)MTT_ERR_RANGE, Py_None);
    st = mtt_params_get(&self->par, key, v, (size_t)n);
    if (st != MTT_OK)
        return Py_BuildValue("(iO)", (int)st, Py_None);
    t = PyTuple_New(n);
    if (t == NULL)
        return NULL;
    for (i = 0; i < n; ++i)
        PyTuple_SET_ITEM(t, i, PyFloat_FromDouble(v[i]));
    return Py_BuildValue("(iN)", (int)st, t);
}

/* check() -> (status, bad field or None) of mtt_params_check */
static PyObject *tracker_check(CoreTracker *self, PyObject *unused)
{
    const char *bad = NULL;
    mtt_status st = mtt_params_check(&self->par, &bad);
    (void)unused;
    return Py_BuildValue("(iz)", (int)st, bad);
}

/* init() -> status of mtt_tracker_init with the parameters set so far */
static PyObject *tracker_start(CoreTracker *self, PyObject *unused)
{
    mtt_tracker *trk;
    mtt_status st;
    (void)unused;
    if (self->trk != NULL) {
        PyErr_SetString(PyExc_RuntimeError, "the tracker is already initialised");
        return NULL;
    }
    trk = PyMem_Malloc(sizeof *trk);
    if (trk == NULL)
        return PyErr_NoMemory();
    memset(trk, 0, sizeof *trk);
    st = mtt_tracker_init(trk, &self->par);
    if (st != MTT_OK) {
        PyMem_Free(trk);
        return PyLong_FromLong((long)st);
    }
    self->trk = trk;
    return PyLong_FromLong((long)MTT_OK);
}

static int need_init(const CoreTracker *self)
{
    if (self->trk == NULL) {
        PyErr_SetString(PyExc_RuntimeError, "the tracker is not initialised");
        return 0;
    }
    return 1;
}

/* add_track(x[4], P[16]) -> (status, id or None) of mtt_tracker_add_track */
static PyObject *tracker_add_track(CoreTracker *self, PyObject *args)
{
    PyObject *xs, *Ps;
    double x[4], P[16];
    mtt_real rx[4], rP[16];
    uint32_t id = 0;
    mtt_status st;
    int k;
    if (!PyArg_ParseTuple(args, "OO", &xs, &Ps))
        return NULL;
    if (!need_init(self) || !numbers(xs, x, 4, "add_track x") || !numbers(Ps, P, 16, "add_track P"))
        return NULL;
    for (k = 0; k < 4; ++k)
        if (!to_real(x[k], &rx[k]))
            return Py_BuildValue("(iO)", (int)MTT_ERR_VALUE, Py_None);
    for (k = 0; k < 16; ++k)
        if (!to_real(P[k], &rP[k]))
            return Py_BuildValue("(iO)", (int)MTT_ERR_VALUE, Py_None);
    st = mtt_tracker_add_track(self->trk, rx, rP, &id);
    if (st != MTT_OK)
        return Py_BuildValue("(iO)", (int)st, Py_None);
    return Py_BuildValue("(ik)", (int)st, (unsigned long)id);
}

/* step(time, buffer[, cov]) -> status of mtt_tracker_step_cov.  buffer: n
 * rows of 3 float64 (x, y, amplitude; NaN amplitude = unknown), already
 * validated by tracker.py (finite coordinates within mtt_real, amplitude >= 0
 * or NaN); cov: n rows of 3 float64 (r_xx, r_xy, r_yy; all 0: meas_sigma's),
 * or None; polar (nonzero): rows of 4 float64, range, bearing, amplitude,
 * range rate (NaN: none), stepped with mtt_tracker_step_polar (ALGORITHMS.md
 * §3.2), cov None. */
static PyObject *tracker_step(CoreTracker *self, PyObject *args)
{
    double time;
    Py_buffer buf, cbuf;
    PyObject *cobj = Py_None;
    mtt_real rtime;
    mtt_meas *meas = NULL;
    mtt_meas_cov *cov = NULL;
    mtt_polar *pol = NULL;
    size_t n, i;
    mtt_status st;
    const double *v;
    int has_cov, polar = 0;
    size_t w;

    if (!PyArg_ParseTuple(args, "dy*|Oi", &time, &buf, &cobj, &polar))
        return NULL;
    has_cov = cobj != Py_None;
    if (has_cov && PyObject_GetBuffer(cobj, &cbuf, PyBUF_SIMPLE) != 0) {
        PyBuffer_Release(&buf);
        return NULL;
    }
    if (!need_init(self)) {
        PyBuffer_Release(&buf);
        if (has_cov)
            PyBuffer_Release(&cbuf);
        return NULL;
    }
    w = polar ? 4u : 3u;
    if (buf.len % (Py_ssize_t)(w * sizeof(double)) != 0 || (has_cov && (polar || cbuf.len != buf.len))) {
        PyBuffer_Release(&buf);
        if (has_cov)
            PyBuffer_Release(&cbuf);
        PyErr_SetString(PyExc_ValueError, "step: the buffers must hold rows of 3 float64 (polar: 4, no cov), "
                                          "as many of each");
        return NULL;
    }
    if (!to_real(time, &rtime)) {
        PyBuffer_Release(&buf);
        if (has_cov)
            PyBuffer_Release(&cbuf);
        return PyLong_FromLong((long)MTT_ERR_TIME);
    }
    n = (size_t)buf.len / (w * sizeof(double));
    v = (const double *)buf.buf;
    if (n != 0) {
        meas = PyMem_Malloc(n * sizeof *meas);
        cov = has_cov ? PyMem_Malloc(n * sizeof *cov) : NULL;
        pol = polar ? PyMem_Malloc(n * sizeof *pol) : NULL;
        if (meas == NULL || (has_cov && cov == NULL) || (polar && pol == NULL)) {
            PyMem_Free(pol);
            PyMem_Free(meas);
            PyMem_Free(cov);
            PyBuffer_Release(&buf);
            if (has_cov)
                PyBuffer_Release(&cbuf);
            return PyErr_NoMemory();
        }
        for (i = 0; i < n; ++i) {
            const double *r = v + w * i;
            meas[i].x = (mtt_real)r[0];
            meas[i].y = (mtt_real)r[1];
            meas[i].has_amplitude = !isnan(r[2]);
            meas[i].amplitude = meas[i].has_amplitude ? (mtt_real)r[2] : MTT_R(0.0);
            if (pol != NULL) {
                pol[i].range = meas[i].x;
                pol[i].bearing = meas[i].y;
                pol[i].amplitude = meas[i].amplitude;
                pol[i].has_amplitude = meas[i].has_amplitude;
                pol[i].has_range_rate = !isnan(r[3]);
                pol[i].range_rate = pol[i].has_range_rate ? (mtt_real)r[3] : MTT_R(0.0);
            }
            if (cov != NULL) {
                const double *c = (const double *)cbuf.buf + 3 * i;
                cov[i].r_xx = (mtt_real)c[0];
                cov[i].r_xy = (mtt_real)c[1];
                cov[i].r_yy = (mtt_real)c[2];
            }
        }
    }
    /* The GIL stays held: two threads stepping one tracker would race (the
     * library is not thread-safe per tracker), and a step is short. */
    st = polar ? mtt_tracker_step_polar(self->trk, rtime, pol, n) : mtt_tracker_step_cov(self->trk, rtime, meas, cov, n);
    PyMem_Free(pol);
    PyMem_Free(meas);
    PyMem_Free(cov);
    PyBuffer_Release(&buf);
    if (has_cov)
        PyBuffer_Release(&cbuf);
    return PyLong_FromLong((long)st);
}

/* table() -> bytes: one row of TABLE_COLUMNS float64 per live track, ascending id:
 * id, confirmed, x, y, vx, vy, existence, age, detection, P (16, row-major),
 * n_models, mu (MTT_MAX_MODELS; motion = imm: the model probabilities),
 * p_split and parent (split = true: P(split) and the parent's id, -1 for none;
 * 0 and -1 otherwise).
 * One call per step instead of one tuple per track (mtt_sim's Monte Carlo). */
#define TABLE_COLUMNS (28 + MTT_MAX_MODELS)
static PyObject *tracker_table(CoreTracker *self, PyObject *unused)
{
    size_t n = 0, i;
    PyObject *bytes;
    double *row;
    int k;
    (void)unused;
    if (!need_init(self))
        return NULL;
    if (mtt_tracker_count(self->trk, &n) != MTT_OK) {
        PyErr_SetString(PyExc_RuntimeError, "mtt_tracker_count failed");
        return NULL;
    }
    bytes = PyBytes_FromStringAndSize(NULL, (Py_ssize_t)(n * TABLE_COLUMNS * sizeof(double)));
    if (bytes == NULL)
        return NULL;
    row = (double *)(void *)PyBytes_AS_STRING(bytes);
    for (i = 0; i < n; ++i, row += TABLE_COLUMNS) {
        mtt_track_view tv;
        if (mtt_tracker_track(self->trk, i, &tv) != MTT_OK) {
            Py_DECREF(bytes);
            PyErr_SetString(PyExc_RuntimeError, "mtt_tracker_track failed");
            return NULL;
        }
        row[0] = (double)tv.id;
        row[1] = tv.confirmed ? 1.0 : 0.0;
        for (k = 0; k < 4; ++k)
            row[2 + k] = (double)tv.x[k];
        row[6] = (double)tv.existence;
        row[7] = (double)tv.age;
        row[8] = (double)tv.meas;
        for (k = 0; k < 16; ++k)
            row[9 + k] = (double)tv.P[k / 4][k % 4];
        row[25] = (double)tv.n_models;
        for (k = 0; k < MTT_MAX_MODELS; ++k)
            row[26 + k] = (double)tv.mu[k];
        row[26 + MTT_MAX_MODELS] = (double)tv.p_split;
        row[27 + MTT_MAX_MODELS] = tv.parent == MTT_NO_PARENT ? -1.0 : (double)tv.parent;
    }
    return bytes;
}

/* The fields of mtt_counts, in order (COUNT_FIELDS). */
#define COUNT_FIELDS(X)                                                                            \
    X(frames) X(meas_in) X(meas_bad) X(meas_dropped) X(pairs) X(pairs_dropped) X(gated_dropped)   \
    X(clusters) X(births) X(births_dropped) X(merges) X(merge_dropped) X(deletions)               \
    X(numeric_deletions) X(confirmations) X(assign_fallbacks) X(jpda_fallbacks) X(splits)         \
    X(split_dropped) X(meas_out_of_range)

/* A field added to mtt_counts must be added to COUNT_FIELDS: this breaks the
 * build until it is (every field is a uint32_t). */
#define COUNT_ONE(f) +1
typedef char count_fields_cover_mtt_counts[(sizeof(mtt_counts) ==
                                            (0 COUNT_FIELDS(COUNT_ONE)) * sizeof(uint32_t)) ? 1 : -1];
#undef COUNT_ONE

static PyObject *counts_dict(const mtt_counts *c)
{
    PyObject *d = PyDict_New(), *v;
    if (d == NULL)
        return NULL;
#define PUT_COUNT(f)                                                                               \
    v = PyLong_FromUnsignedLong((unsigned long)c->f);                                              \
    if (v == NULL || PyDict_SetItemString(d, #f, v) != 0) {                                        \
        Py_XDECREF(v);                                                                             \
        Py_DECREF(d);                                                                              \
        return NULL;                                                                               \
    }                                                                                              \
    Py_DECREF(v);
    COUNT_FIELDS(PUT_COUNT)
#undef PUT_COUNT
    return d;
}

/* stats() -> (last dict, total dict, max_cluster_tracks) */
static PyObject *tracker_stats(CoreTracker *self, PyObject *unused)
{
    mtt_stats s;
    (void)unused;
    if (!need_init(self))
        return NULL;
    if (mtt_tracker_stats(self->trk, &s) != MTT_OK) {
        PyErr_SetString(PyExc_RuntimeError, "mtt_tracker_stats failed");
        return NULL;
    }
    return Py_BuildValue("(NNk)", counts_dict(&s.last), counts_dict(&s.total),
                         (unsigned long)s.max_cluster_tracks);
}

/* state_bytes() -> the whole mtt_tracker as bytes (tests: nothing changed) */
static PyObject *tracker_state_bytes(CoreTracker *self, PyObject *unused)
{
    (void)unused;
    if (!need_init(self))
        return NULL;
    return PyBytes_FromStringAndSize((const char *)self->trk, (Py_ssize_t)sizeof *self->trk);
}

static PyMethodDef tracker_methods[] = {
    {"set_param", (PyCFunction)tracker_set_param, METH_VARARGS,
     "set_param(key, values) -> status of mtt_params_set"},
    {"get_param", (PyCFunction)tracker_get_param, METH_VARARGS,
     "get_param(key, n) -> (status, values) of mtt_params_get"},
    {"check", (PyCFunction)tracker_check, METH_NOARGS,
     "check() -> (status, bad key) of mtt_params_check"},
    {"init", (PyCFunction)tracker_start, METH_NOARGS, "init() -> status of mtt_tracker_init"},
    {"add_track", (PyCFunction)tracker_add_track, METH_VARARGS,
     "add_track(x, P) -> (status, id) of mtt_tracker_add_track"},
    {"step", (PyCFunction)tracker_step, METH_VARARGS,
     "step(time, float64 rows x, y, amplitude[, cov rows[, polar]]) -> status of mtt_tracker_step_cov "
     "(polar: rows range, bearing, amplitude, mtt_tracker_step_polar)"},
    {"table", (PyCFunction)tracker_table, METH_NOARGS,
     "table() -> bytes, TABLE_COLUMNS float64 per live track (see TABLE_NAMES)"},
    {"stats", (PyCFunction)tracker_stats, METH_NOARGS, "stats() -> (last, total, max_cluster_tracks)"},
    {"state_bytes", (PyCFunction)tracker_state_bytes, METH_NOARGS,
     "state_bytes() -> the tracker state as bytes"},
    {NULL, NULL, 0, NULL}};

static PyTypeObject TrackerType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "mtt._core.Tracker",
    .tp_basicsize = sizeof(CoreTracker),
    .tp_itemsize = 0,
    .tp_dealloc = (destructor)tracker_dealloc,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "One mtt_tracker: set_param / check / init, then add_track, step, table, stats.",
    .tp_methods = tracker_methods,
    .tp_init = (initproc)tracker_init,
    .tp_new = PyType_GenericNew,
};

static PyMethodDef core_methods[] = {
    {"params_info", core_params_info, METH_NOARGS,
     "params_info() -> list of (key, type, count, lo, hi, lo_open, hi_open, names, cross, text, per_model)"},
    {"status_text", core_status_text, METH_VARARGS, "status_text(status) -> text"},
    {"two_point_cov", core_two_point_cov, METH_VARARGS,
     "two_point_cov(sx, sy, dt) -> (status, 16 values) of mtt_init_two_point_cov"},
    {NULL, NULL, 0, NULL}};

static struct PyModuleDef core_module = {PyModuleDef_HEAD_INIT, "_core",
                                         "The mtt C library (mtt.Tracker uses it).", -1,
                                         core_methods, NULL, NULL, NULL, NULL};

PyMODINIT_FUNC PyInit__core(void)
{
    PyObject *m, *fields;
    if (PyType_Ready(&TrackerType) < 0)
        return NULL;
    m = PyModule_Create(&core_module);
    if (m == NULL)
        return NULL;
    Py_INCREF(&TrackerType);
    if (PyModule_AddObject(m, "Tracker", (PyObject *)&TrackerType) < 0) {
        Py_DECREF(&TrackerType);
        Py_DECREF(m);
        return NULL;
    }
    {
        /* one name per field, however many COUNT_FIELDS has */
#define NAME_OF(f) #f,
        static const char *const names[] = {COUNT_FIELDS(NAME_OF)};
#undef NAME_OF
        const Py_ssize_t nf = (Py_ssize_t)(sizeof names / sizeof names[0]);
        Py_ssize_t k;
        fields = PyTuple_New(nf);
        for (k = 0; fields != NULL && k < nf; ++k) {
            PyObject *o = PyUnicode_FromString(names[k]);
            if (o == NULL) {
                Py_CLEAR(fields);
                break;
            }
            PyTuple_SET_ITEM(fields, k, o);
        }
    }
    if (fields == NULL || PyModule_AddObject(m, "COUNT_FIELDS", fields) < 0 ||
        PyModule_AddStringConstant(m, "VERSION", MTT_VERSION_STRING) < 0 ||
        PyModule_AddStringConstant(m, "REAL", REAL_NAME) < 0 ||
        PyModule_AddObject(m, "REAL_MAX", PyFloat_FromDouble((double)MTT_REAL_MAX)) < 0 ||
        PyModule_AddIntConstant(m, "MAX_TRACKS", MTT_MAX_TRACKS) < 0 ||
        PyModule_AddIntConstant(m, "MAX_MODELS", MTT_MAX_MODELS) < 0 ||
        PyModule_AddIntConstant(m, "MODEL_VALUES", MTT_PARAM_MODEL_VALUES) < 0 ||
        PyModule_AddIntConstant(m, "TABLE_COLUMNS", TABLE_COLUMNS) < 0 ||
        PyModule_AddIntConstant(m, "MAX_MEAS", MTT_MAX_MEAS) < 0 ||
        PyModule_AddIntConstant(m, "ERR_TIME", MTT_ERR_TIME) < 0 ||
        PyModule_AddIntConstant(m, "ERR_VALUE", MTT_ERR_VALUE) < 0 ||
        PyModule_AddIntConstant(m, "ERR_FULL", MTT_ERR_FULL) < 0 ||
        PyModule_AddIntConstant(m, "ERR_PARAM", MTT_ERR_PARAM) < 0 ||
        PyModule_AddIntConstant(m, "ERR_RANGE", MTT_ERR_RANGE) < 0 ||
        PyModule_AddIntConstant(m, "ERR_UNSUPPORTED", MTT_ERR_UNSUPPORTED) < 0) {
        Py_DECREF(m);
        return NULL;
    }
    return m;
}
