# Two modules, high building on low: low including high is the forbidden edge the check must find.
set(VISEMELAB_DEPENDS_low)
set(VISEMELAB_DEPENDS_high low)
set(VISEMELAB_CORE_MODULES low high)
