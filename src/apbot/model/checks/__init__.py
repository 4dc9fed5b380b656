"""The semantic checks of :func:`apbot.model.validate.check_model`, one module per concern."""
