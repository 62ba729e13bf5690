"""GaussianMixture over nl_gmm (stats/nl_gmm.h), scikit-learn's names."""

import ctypes
from typing import Any, Dict, Optional, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._lib import Error, c_double_p, check, fn, mirror
from ._lib import integer as _int, real as _real

__all__ = ["GaussianMixture"]


@mirror("nl_gmm_options")
class _Options(ctypes.Structure):
    _fields_ = [("covariance", ctypes.c_int), ("tol", ctypes.c_double),
                ("reg_covar", ctypes.c_double), ("max_iter", ctypes.c_size_t),
                ("seed", ctypes.c_ulong), ("init_labels", ctypes.POINTER(ctypes.c_int)),
                ("threads", ctypes.c_int), ("memo", ctypes.c_void_p),
                ("workspace", ctypes.c_void_p)]


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

_COV = {"full": 0, "diag": 1, "tied": 2, "spherical": 3}
_PARAMS = ("n_components", "covariance_type", "tol", "reg_covar", "max_iter", "random_state",
           "n_threads")


def _ptr(a):
    return a.ctypes.data_as(c_double_p)


def _array(p, shape):
    n = int(np.prod(shape))
    return np.ctypeslib.as_array(p, shape=(n,)).copy().reshape(shape)


def _seed(random_state):
    """The library's k-means++ seed from sklearn's random_state: an int (stat
    gmm's range), None (numpy's global RandomState, as sklearn), a
    RandomState or a Generator (one draw from it)."""
    if random_state is None:
        return int(np.random.mtrand._rand.randint(0, 2**32, dtype=np.uint64))
    if isinstance(random_state, np.random.RandomState):
        return int(random_state.randint(0, 2**32, dtype=np.uint64))
    if isinstance(random_state, np.random.Generator):
        return int(random_state.integers(0, 2**32, dtype=np.uint64))
    return _int("random_state", random_state, 0, 2**32 - 1)


class GaussianMixture:
    """A Gaussian mixture fitted by EM, as sklearn.mixture.GaussianMixture.

    EM is scikit-learn's step for step (stats/nl_gmm.h): from the same initial
    labels both reach the same log-likelihood to 1e-8 relative in the same
    number of iterations, for each of the four covariance types.
    Initialisation: k-means++ seeding from random_state and Lloyd iterations,
    or the labels given to fit(X, init_labels=...).

    An estimator as scikit-learn's: the constructor only stores its
    arguments (checked at fit), get_params/set_params, sklearn.base.clone and
    pickle work, and so do fit_predict, predict_proba and sample.

    Parameters
    ----------
    n_components : int
    covariance_type : 'full', 'tied', 'diag' or 'spherical'
    tol : float            stop when the mean log-likelihood changes by less (1e-3)
    reg_covar : float      added to every variance (1e-6)
    max_iter : int         (100)
    random_state : int, None, numpy RandomState or Generator
                           the k-means++ seed (0: reproducible by default; None
                           draws one from numpy's global state, as sklearn's
                           default) and the stream of sample()
    n_threads : int        threads for EM; results do not depend on it (1)

    Attributes after fit: weights_, means_, covariances_ (sklearn's shapes:
    full (k, d, d), tied (d, d), diag (k, d), spherical (k,)), precisions_,
    precisions_cholesky_, converged_, n_iter_, n_features_in_, lower_bound_
    (the mean log-likelihood of the final parameters; sklearn's is that of the
    last E-step, before the last M-step: they differ by less than tol when
    converged).

    Example
    -------
    >>> import numpy as np
    >>> from noiselab.stats import GaussianMixture
    >>> rng = np.random.default_rng(0)
    >>> X = np.vstack([rng.normal(0, 1, (200, 2)), rng.normal(8, 1, (200, 2))])
    >>> g = GaussianMixture(2, random_state=1).fit(X)
    >>> sorted(np.round(g.means_[:, 0]).tolist())
    [0.0, 8.0]
    >>> Xs, ys = g.sample(4)
    >>> Xs.shape, ys.shape
    ((4, 2), (4,))
    """

    def __init__(self, n_components: int = 1, *, covariance_type: str = "full",
                 tol: float = 1e-3, reg_covar: float = 1e-6, max_iter: int = 100,
                 random_state: Union[None, int, np.random.RandomState,
                                     np.random.Generator] = 0,
                 n_threads: int = 1) -> None:
        # Stored as given (sklearn.base.clone checks that), checked at fit.
        self.n_components = n_components
        self.covariance_type = covariance_type
        self.tol = tol
        self.reg_covar = reg_covar
        self.max_iter = max_iter
        self.random_state = random_state
        self.n_threads = n_threads
        self._g = None

    def get_params(self, deep: bool = True) -> Dict[str, Any]:
        """The constructor's arguments, by name (sklearn's get_params)."""
        return {name: getattr(self, name) for name in _PARAMS}

    def set_params(self, **params: Any) -> "GaussianMixture":
        """Sets constructor arguments by name (checked at the next fit); returns self."""
        for name, value in params.items():
            if name not in _PARAMS:
                raise ValueError(f"set_params: {name!r} is not a parameter of GaussianMixture "
                                 f"({', '.join(_PARAMS)})")
            setattr(self, name, value)
        return self

    def __repr__(self):
        changed = [f"{k}={v!r}" for k, v in self.get_params().items()
                   if k == "n_components" or v != GaussianMixture().get_params()[k]]
        return f"GaussianMixture({', '.join(changed)})"

    def __del__(self):
        if getattr(self, "_g", None):
            _free(self._g)
            self._g = None

    # Pickling: the fitted C model travels as its arrays and is rebuilt.
    def __getstate__(self):
        state = {k: v for k, v in self.__dict__.items() if k != "_g"}
        if self._g:
            c = self._g.contents
            per = c.d * c.d if c.covariance in (0, 2) else c.d
            state["_model"] = dict(
                k=c.k, d=c.d, covariance=c.covariance,
                arrays={name: _array(getattr(c, name), (n,)) for name, n in
                        (("weights", c.k), ("means", c.k * c.d), ("covs", c.k * per),
                         ("chol", c.k * per), ("prec", c.k * per)) if getattr(c, name)},
                scalars={name: getattr(c, name) for name in
                         ("n", "loglik", "aic", "bic", "nparams", "iterations", "converged")})
        return state

    def __setstate__(self, state):
        model = state.pop("_model", None)
        self.__dict__.update(state)
        self._g = None
        if model:
            g = _alloc(model["k"], model["d"], model["covariance"])
            c = g.contents
            for name, a in model["arrays"].items():
                a = np.ascontiguousarray(a, dtype=np.float64)
                ctypes.memmove(getattr(c, name), a.ctypes.data, a.nbytes)
            for name, v in model["scalars"].items():
                setattr(c, name, v)
            self._g = g

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

    def fit(self, X: ArrayLike, y: Any = None, *,
            init_labels: Optional[ArrayLike] = None) -> "GaussianMixture":
        """Fits the mixture to the rows of X; returns self.

        init_labels: n labels in 0..n_components-1 to start EM from (one-hot
        responsibilities, then an M-step), instead of k-means.
        """
        if self.covariance_type not in _COV:
            raise ValueError(f"covariance_type: {self.covariance_type!r} is not 'full', 'tied', "
                             f"'diag' or 'spherical'")
        k = _int("n_components", self.n_components, 1, 2**62)
        # tol, reg_covar and max_iter are checked by the library
        # (nl_gmm_options_check, `stat gmm`'s ranges); here what C holds
        tol, reg_covar = _real("tol", self.tol), _real("reg_covar", self.reg_covar)
        max_iter = _int("max_iter", self.max_iter, 0, 2**62)
        threads = _int("n_threads", self.n_threads, 1, 2**31 - 1)
        seed = _seed(self.random_state)
        if self._g:   # a refit: the features of X are its own
            _free(self._g)
            self._g = None
        x = self._rows(X)
        n, d = x.shape
        cov = _COV[self.covariance_type]
        err = Error()
        check(_check_size(n, d, k, cov, ctypes.byref(err)), err)
        o = _Options()
        _defaults(ctypes.byref(o))
        o.covariance, o.tol, o.reg_covar = cov, tol, reg_covar
        o.max_iter, o.seed, o.threads = max_iter, seed, threads
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
        self._g = g
        c = g.contents
        self.weights_ = _array(c.weights, (k,))
        self.means_ = _array(c.means, (k, d))
        if cov in (0, 2):
            covs = _array(c.covs, (k, d, d))
            self.covariances_ = covs if cov == 0 else covs[0].copy()
            # sklearn's precisions_cholesky_: the upper factor U with U U^T the
            # precision, i.e. (L^{-1})^T for Sigma = L L^T (nl_gmm's prec is L^{-1})
            linv = _array(c.prec, (k, d, d))
            pc = np.transpose(linv, (0, 2, 1))
            self.precisions_cholesky_ = pc if cov == 0 else pc[0].copy()
            prec = pc @ np.transpose(pc, (0, 2, 1))
            self.precisions_ = prec if cov == 0 else prec[0].copy()
        else:
            var = _array(c.covs, (k, d))
            self.covariances_ = var if cov == 1 else var[:, 0].copy()
            self.precisions_ = 1.0 / self.covariances_
            self.precisions_cholesky_ = 1.0 / np.sqrt(self.covariances_)
        self.converged_ = bool(c.converged)
        self.n_iter_ = int(c.iterations)
        self.lower_bound_ = c.loglik / n
        self.n_features_in_ = d
        return self

    def fit_predict(self, X: ArrayLike, y: Any = None) -> NDArray[np.intp]:
        """Fits, then the most probable component of each row (sklearn's fit_predict)."""
        return self.fit(X).predict(X)

    def sample(self, n_samples: int = 1) -> Tuple[NDArray[np.float64], NDArray[np.intp]]:
        """n_samples draws from the fitted mixture: (X, y), rows grouped by
        component as sklearn's (counts from a multinomial, then each
        component's normal draws), from random_state's stream."""
        self._fitted()
        n = _int("n_samples", n_samples, 1, 2**62)
        rs = self.random_state
        rng = rs if isinstance(rs, (np.random.RandomState, np.random.Generator)) else \
            np.random.RandomState(None if rs is None else _seed(rs))
        counts = rng.multinomial(n, self.weights_)
        d, cov = self.means_.shape[1], self.covariance_type
        parts, labels = [], []
        for j, m in enumerate(counts):
            if cov == "full":
                z = rng.multivariate_normal(self.means_[j], self.covariances_[j], int(m))
            elif cov == "tied":
                z = rng.multivariate_normal(self.means_[j], self.covariances_, int(m))
            else:
                sd = np.sqrt(self.covariances_[j]) * np.ones(d)
                z = self.means_[j] + rng.standard_normal((int(m), d)) * sd
            parts.append(z)
            labels.append(np.full(int(m), j, dtype=int))
        return np.vstack(parts), np.concatenate(labels)

    def _fitted(self):
        if not self._g:
            raise ValueError("GaussianMixture: not fitted yet; call fit(X) first")
        return self._g

    def score_samples(self, X: ArrayLike) -> NDArray[np.float64]:
        """log p(x_i) of each row under the mixture."""
        g = self._fitted()
        x = self._rows(X)
        total, logp, err = ctypes.c_double(), np.empty(x.shape[0]), Error()
        check(_loglik(g, _ptr(x), x.shape[0], ctypes.byref(total), _ptr(logp),
                      ctypes.byref(err)), err)
        return logp

    def score(self, X: ArrayLike, y: Any = None) -> float:
        """The mean log-likelihood of the rows of X (sklearn's score)."""
        g = self._fitted()
        x = self._rows(X)
        total, err = ctypes.c_double(), Error()
        check(_loglik(g, _ptr(x), x.shape[0], ctypes.byref(total), None, ctypes.byref(err)), err)
        return total.value / x.shape[0]

    def _n_parameters(self):
        c = self._fitted().contents
        return int(_nparams(c.k, c.d, c.covariance))

    def aic(self, X: ArrayLike) -> float:
        """Akaike's criterion on X: -2 log L + 2 m (sklearn's aic)."""
        return -2 * self.score(X) * np.asarray(X).shape[0] + 2 * self._n_parameters()

    def bic(self, X: ArrayLike) -> float:
        """Schwarz's criterion on X: -2 log L + m ln n (sklearn's bic)."""
        n = np.asarray(X).shape[0]
        return -2 * self.score(X) * n + self._n_parameters() * np.log(n)

    def _component_logpdf(self, x):
        """log w_k + log N(x_i; mu_k, Sigma_k), n x k, each density from the
        library (a one-component model holding component k's parameters)."""
        g = self._fitted().contents
        k, d, cov = g.k, g.d, g.covariance
        per = d * d if cov in (0, 2) else d
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

    def predict_proba(self, X: ArrayLike) -> NDArray[np.float64]:
        """Responsibilities: the posterior probability of each component, n x k."""
        lp = self._component_logpdf(self._rows(X))
        m = lp.max(axis=1, keepdims=True)
        p = np.exp(lp - m)
        return p / p.sum(axis=1, keepdims=True)

    def predict(self, X: ArrayLike) -> NDArray[np.intp]:
        """The most probable component of each row."""
        return np.argmax(self._component_logpdf(self._rows(X)), axis=1)
