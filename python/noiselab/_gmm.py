"""GaussianMixture over nl_gmm (stats/nl_gmm.h), scikit-learn's names."""

import ctypes

import numpy as np

from ._lib import Error, c_double_p, check, fn, mirror
from ._lib import integer as _int, real as _real

__all__ = ["GaussianMixture"]


@mirror("nl_gmm_options")
class _Options(ctypes.Structure):
    _fields_ = [("covariance", ctypes.c_int), ("tol", ctypes.c_double),
                ("reg_covar", ctypes.c_double), ("max_iter", ctypes.c_size_t),
                ("seed", ctypes.c_ulong), ("init_labels", ctypes.POINTER(ctypes.c_int)),
                ("threads", ctypes.c_int), ("memo", ctypes.c_void_p)]


@mirror("nl_gmm")
class _Gmm(ctypes.Structure):
    _fields_ = [("k", ctypes.c_size_t), ("d", ctypes.c_size_t), ("covariance", ctypes.c_int),
                ("weights", c_double_p), ("means", c_double_p), ("covs", c_double_p),
                ("chol", c_double_p), ("prec", c_double_p), ("n", ctypes.c_size_t),
                ("loglik", ctypes.c_double), ("aic", ctypes.c_double), ("bic", ctypes.c_double),
                ("nparams", ctypes.c_size_t), ("iterations", ctypes.c_size_t),
                ("converged", ctypes.c_int)]


# nl_gmm_options_check names the options as `stat gmm` spells them.
_NAMES = {"--tol": "tol", "--reg-covar": "reg_covar", "--max-iter": "max_iter"}


_P = ctypes.POINTER(_Gmm)
_E = ctypes.POINTER(Error)
_defaults = fn("nl_gmm_options_default", None, ctypes.POINTER(_Options))
_alloc = fn("nl_gmm_alloc", _P, ctypes.c_size_t, ctypes.c_size_t, ctypes.c_int)
_free = fn("nl_gmm_free", None, _P)
_check_size = fn("nl_gmm_check_size", ctypes.c_int, ctypes.c_size_t, ctypes.c_size_t,
                 ctypes.c_size_t, ctypes.c_int, _E)
_fit = fn("nl_gmm_fit", ctypes.c_int, _P, c_double_p, ctypes.c_size_t,
          ctypes.POINTER(_Options), _E)
_loglik = fn("nl_gmm_loglik", ctypes.c_int, _P, c_double_p, ctypes.c_size_t,
             ctypes.POINTER(ctypes.c_double), c_double_p, _E)
_nparams = fn("nl_gmm_nparams", ctypes.c_size_t, ctypes.c_size_t, ctypes.c_size_t, ctypes.c_int)

_COV = {"full": 0, "diag": 1}


def _ptr(a):
    return a.ctypes.data_as(c_double_p)


def _array(p, shape):
    n = int(np.prod(shape))
    return np.ctypeslib.as_array(p, shape=(n,)).copy().reshape(shape)


class GaussianMixture:
    """A Gaussian mixture fitted by EM, as sklearn.mixture.GaussianMixture.

    EM is scikit-learn's step for step (stats/nl_gmm.h): from the same initial
    labels both reach the same log-likelihood to 1e-8 relative in the same
    number of iterations. Initialisation: k-means++ seeding from random_state
    and Lloyd iterations, or the labels given to fit(X, init_labels=...).

    Parameters
    ----------
    n_components : int
    covariance_type : 'full' or 'diag'
    tol : float            stop when the mean log-likelihood changes by less (1e-3)
    reg_covar : float      added to every variance (1e-6)
    max_iter : int         (100)
    random_state : int     the k-means++ seed (0)
    n_threads : int        threads for EM; results do not depend on it (1)

    Attributes after fit: weights_, means_, covariances_, converged_, n_iter_,
    lower_bound_ (the mean log-likelihood of the final parameters).

    Example
    -------
    >>> import numpy as np
    >>> from noiselab.stats import GaussianMixture
    >>> rng = np.random.default_rng(0)
    >>> X = np.vstack([rng.normal(0, 1, (200, 2)), rng.normal(8, 1, (200, 2))])
    >>> g = GaussianMixture(2, random_state=1).fit(X)
    >>> sorted(np.round(g.means_[:, 0]).tolist())
    [0.0, 8.0]
    """

    def __init__(self, n_components=1, *, covariance_type="full", tol=1e-3, reg_covar=1e-6,
                 max_iter=100, random_state=0, n_threads=1):
        if covariance_type not in _COV:
            raise ValueError(f"covariance_type: {covariance_type!r} is not 'full' or 'diag'")
        self.n_components = _int("n_components", n_components, 1, 2**62)
        self.covariance_type = covariance_type
        # tol, reg_covar and max_iter are checked by the library at fit
        # (nl_gmm_options_check, `stat gmm`'s ranges); here what C holds
        self.tol, self.reg_covar = _real("tol", tol), _real("reg_covar", reg_covar)
        self.max_iter = _int("max_iter", max_iter, 0, 2**62)
        # `stat gmm --seed`'s range
        self.random_state = _int("random_state", random_state, 0, 2**32 - 1)
        self.n_threads = _int("n_threads", n_threads, 1, 2**31 - 1)
        self._g = None

    def __del__(self):
        if getattr(self, "_g", None):
            _free(self._g)
            self._g = None

    def _rows(self, X):
        x = np.asarray(X)
        if x.dtype.kind not in "biuf":
            raise TypeError(f"X: expected real numbers, got dtype {x.dtype}")
        x = np.ascontiguousarray(x, dtype=np.float64)
        if x.ndim != 2:
            raise ValueError(f"X: expected a 2-D array (n_samples, n_features), got shape "
                             f"{x.shape}")
        if self._g and x.shape[1] != self._g.contents.d:
            raise ValueError(f"X: {x.shape[1]} features; the model was fitted to "
                             f"{self._g.contents.d}")
        return x

    def fit(self, X, y=None, *, init_labels=None):
        """Fits the mixture to the rows of X; returns self.

        init_labels: n labels in 0..n_components-1 to start EM from (one-hot
        responsibilities, then an M-step), instead of k-means.
        """
        x = self._rows(X)
        n, d = x.shape
        k, cov = self.n_components, _COV[self.covariance_type]
        err = Error()
        check(_check_size(n, d, k, cov, ctypes.byref(err)), err)
        o = _Options()
        _defaults(ctypes.byref(o))
        o.covariance, o.tol, o.reg_covar = cov, self.tol, self.reg_covar
        o.max_iter, o.seed, o.threads = self.max_iter, self.random_state, self.n_threads
        labels = None
        if init_labels is not None:
            labels = np.ascontiguousarray(init_labels, dtype=np.intc)
            if labels.shape != (n,):
                raise ValueError(f"init_labels: shape {labels.shape}, expected ({n},)")
            o.init_labels = labels.ctypes.data_as(ctypes.POINTER(ctypes.c_int))
        g = _alloc(k, d, cov)
        s = _fit(g, _ptr(x), n, ctypes.byref(o), ctypes.byref(err))
        if s:
            _free(g)
            check(s, err, _NAMES)
        if self._g:
            _free(self._g)
        self._g = g
        c = g.contents
        self.weights_ = _array(c.weights, (k,))
        self.means_ = _array(c.means, (k, d))
        self.covariances_ = _array(c.covs, (k, d, d) if cov == 0 else (k, d))
        self.converged_ = bool(c.converged)
        self.n_iter_ = int(c.iterations)
        self.lower_bound_ = c.loglik / n
        self.n_features_in_ = d
        return self

    def _fitted(self):
        if not self._g:
            raise ValueError("GaussianMixture: not fitted yet; call fit(X) first")
        return self._g

    def score_samples(self, X):
        """log p(x_i) of each row under the mixture."""
        g = self._fitted()
        x = self._rows(X)
        total, logp, err = ctypes.c_double(), np.empty(x.shape[0]), Error()
        check(_loglik(g, _ptr(x), x.shape[0], ctypes.byref(total), _ptr(logp),
                      ctypes.byref(err)), err)
        return logp

    def score(self, X, y=None):
        """The mean log-likelihood of the rows of X (sklearn's score)."""
        g = self._fitted()
        x = self._rows(X)
        total, err = ctypes.c_double(), Error()
        check(_loglik(g, _ptr(x), x.shape[0], ctypes.byref(total), None, ctypes.byref(err)), err)
        return total.value / x.shape[0]

    def _n_parameters(self):
        return int(_nparams(self.n_components, self._fitted().contents.d,
                            _COV[self.covariance_type]))

    def aic(self, X):
        """Akaike's criterion on X: -2 log L + 2 m (sklearn's aic)."""
        return -2 * self.score(X) * np.asarray(X).shape[0] + 2 * self._n_parameters()

    def bic(self, X):
        """Schwarz's criterion on X: -2 log L + m ln n (sklearn's bic)."""
        n = np.asarray(X).shape[0]
        return -2 * self.score(X) * n + self._n_parameters() * np.log(n)

    def _component_logpdf(self, x):
        """log w_k + log N(x_i; mu_k, Sigma_k), n x k, each density from the
        library (a one-component model holding component k's parameters)."""
        g = self._fitted().contents
        k, d, cov = g.k, g.d, g.covariance
        per = d * d if cov == 0 else d
        out = np.empty((x.shape[0], k))
        err = Error()
        for j in range(k):
            one = _alloc(1, d, cov)
            try:
                c = one.contents
                c.weights[0] = 1.0
                ctypes.memmove(c.means, ctypes.addressof(g.means.contents) + 8 * j * d, 8 * d)
                for name in ("covs", "chol", "prec"):
                    src = getattr(g, name)
                    if src:
                        ctypes.memmove(getattr(c, name),
                                       ctypes.addressof(src.contents) + 8 * j * per, 8 * per)
                col = np.empty(x.shape[0])
                total = ctypes.c_double()
                check(_loglik(one, _ptr(x), x.shape[0], ctypes.byref(total), _ptr(col),
                              ctypes.byref(err)), err)
            finally:
                _free(one)
            out[:, j] = col + np.log(g.weights[j])
        return out

    def predict_proba(self, X):
        """Responsibilities: the posterior probability of each component, n x k."""
        lp = self._component_logpdf(self._rows(X))
        m = lp.max(axis=1, keepdims=True)
        p = np.exp(lp - m)
        return p / p.sum(axis=1, keepdims=True)

    def predict(self, X):
        """The most probable component of each row."""
        return np.argmax(self._component_logpdf(self._rows(X)), axis=1)
