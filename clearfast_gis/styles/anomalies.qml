<!DOCTYPE qgis PUBLIC 'http://mrcc.com/qgis.dtd' 'SYSTEM'>
<qgis version="3.22.16-Białowieża" simplifyDrawingTol="1" simplifyLocal="1" minScale="100000000" simplifyDrawingHints="1" symbologyReferenceScale="-1" styleCategories="Symbology|Labeling|Fields|Forms|MapTips|AttributeTable|Rendering" maxScale="0" labelsEnabled="0" hasScaleBasedVisibilityFlag="0" simplifyMaxScale="1" simplifyAlgorithm="0">
  <renderer-v2 enableorderby="0" referencescale="-1" symbollevels="0" forceraster="0" type="categorizedSymbol" attr="polarity">
    <categories>
      <category render="true" symbol="0" label="Warm by day" value="hot"/>
      <category render="true" symbol="1" label="Cool by day" value="cold"/>
    </categories>
    <symbols>
      <symbol alpha="1" clip_to_extent="1" type="fill" name="0" force_rhr="0">
        <data_defined_properties>
          <Option type="Map">
            <Option type="QString" name="name" value=""/>
            <Option name="properties"/>
            <Option type="QString" name="type" value="collection"/>
          </Option>
        </data_defined_properties>
        <layer class="SimpleFill" pass="0" enabled="1" locked="0">
          <Option type="Map">
            <Option type="QString" name="border_width_map_unit_scale" value="3x:0,0,0,0,0,0"/>
            <Option type="QString" name="color" value="0,0,0,0"/>
            <Option type="QString" name="joinstyle" value="bevel"/>
            <Option type="QString" name="offset" value="0,0"/>
            <Option type="QString" name="offset_map_unit_scale" value="3x:0,0,0,0,0,0"/>
            <Option type="QString" name="offset_unit" value="MM"/>
            <Option type="QString" name="outline_color" value="215,48,39,255"/>
            <Option type="QString" name="outline_style" value="solid"/>
            <Option type="QString" name="outline_width" value="0.5"/>
            <Option type="QString" name="outline_width_unit" value="MM"/>
            <Option type="QString" name="style" value="no"/>
          </Option>
          <prop v="3x:0,0,0,0,0,0" k="border_width_map_unit_scale"/>
          <prop v="0,0,0,0" k="color"/>
          <prop v="bevel" k="joinstyle"/>
          <prop v="0,0" k="offset"/>
          <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
          <prop v="MM" k="offset_unit"/>
          <prop v="215,48,39,255" k="outline_color"/>
          <prop v="solid" k="outline_style"/>
          <prop v="0.5" k="outline_width"/>
          <prop v="MM" k="outline_width_unit"/>
          <prop v="no" k="style"/>
          <data_defined_properties>
            <Option type="Map">
              <Option type="QString" name="name" value=""/>
              <Option name="properties"/>
              <Option type="QString" name="type" value="collection"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
      <symbol alpha="1" clip_to_extent="1" type="fill" name="1" force_rhr="0">
        <data_defined_properties>
          <Option type="Map">
            <Option type="QString" name="name" value=""/>
            <Option name="properties"/>
            <Option type="QString" name="type" value="collection"/>
          </Option>
        </data_defined_properties>
        <layer class="SimpleFill" pass="0" enabled="1" locked="0">
          <Option type="Map">
            <Option type="QString" name="border_width_map_unit_scale" value="3x:0,0,0,0,0,0"/>
            <Option type="QString" name="color" value="0,0,0,0"/>
            <Option type="QString" name="joinstyle" value="bevel"/>
            <Option type="QString" name="offset" value="0,0"/>
            <Option type="QString" name="offset_map_unit_scale" value="3x:0,0,0,0,0,0"/>
            <Option type="QString" name="offset_unit" value="MM"/>
            <Option type="QString" name="outline_color" value="69,117,180,255"/>
            <Option type="QString" name="outline_style" value="solid"/>
            <Option type="QString" name="outline_width" value="0.5"/>
            <Option type="QString" name="outline_width_unit" value="MM"/>
            <Option type="QString" name="style" value="no"/>
          </Option>
          <prop v="3x:0,0,0,0,0,0" k="border_width_map_unit_scale"/>
          <prop v="0,0,0,0" k="color"/>
          <prop v="bevel" k="joinstyle"/>
          <prop v="0,0" k="offset"/>
          <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
          <prop v="MM" k="offset_unit"/>
          <prop v="69,117,180,255" k="outline_color"/>
          <prop v="solid" k="outline_style"/>
          <prop v="0.5" k="outline_width"/>
          <prop v="MM" k="outline_width_unit"/>
          <prop v="no" k="style"/>
          <data_defined_properties>
            <Option type="Map">
              <Option type="QString" name="name" value=""/>
              <Option name="properties"/>
              <Option type="QString" name="type" value="collection"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
    </symbols>
    <rotation/>
    <sizescale/>
  </renderer-v2>
  <blendMode>0</blendMode>
  <featureBlendMode>0</featureBlendMode>
  <layerOpacity>1</layerOpacity>
  <fieldConfiguration>
    <field name="anomaly_id" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="x" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="y" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="lat" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="7"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="lon" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="7"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="area_m2" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="3"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="diameter_m" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="circularity" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="depth_m" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="3"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="depth_sigma_m" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="3"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="diffusivity_m2s" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="diffusivity_sigma_m2s" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="status" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="polarity" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="class_cue" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="cue_confidence" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="p_mine" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="priority" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="set_aside_reason" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="n_scans" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="contrast_day_k" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="contrast_night_k" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="mine_curve_r" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="mine_curve_level" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="fix_quality" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="figure" configurationFlags="None">
      <editWidget type="">
        <config>
          <Option/>
        </config>
      </editWidget>
    </field>
    <field name="contrast_series" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="found_by" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="short_id" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="depth" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="diffusivity" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="likelihood" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="cue_confidence_pct" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
  </fieldConfiguration>
  <aliases>
    <alias field="anomaly_id" name="Suspect id" index="0"/>
    <alias field="x" name="Easting (m, survey UTM)" index="1"/>
    <alias field="y" name="Northing (m, survey UTM)" index="2"/>
    <alias field="lat" name="Latitude (°, WGS84)" index="3"/>
    <alias field="lon" name="Longitude (°, WGS84)" index="4"/>
    <alias field="area_m2" name="Area (m²)" index="5"/>
    <alias field="diameter_m" name="Diameter (m)" index="6"/>
    <alias field="circularity" name="Circularity (0-1)" index="7"/>
    <alias field="depth_m" name="Burial depth (m)" index="8"/>
    <alias field="depth_sigma_m" name="Depth uncertainty, 1σ (m)" index="9"/>
    <alias field="diffusivity_m2s" name="Thermal diffusivity (m²/s)" index="10"/>
    <alias field="diffusivity_sigma_m2s" name="Diffusivity uncertainty, 1σ (m²/s)" index="11"/>
    <alias field="status" name="Characterisation status" index="12"/>
    <alias field="polarity" name="Polarity" index="13"/>
    <alias field="class_cue" name="Class cue" index="14"/>
    <alias field="cue_confidence" name="Class cue confidence (0-1)" index="15"/>
    <alias field="p_mine" name="Mine likelihood (0-1)" index="16"/>
    <alias field="priority" name="Priority (1 = first)" index="17"/>
    <alias field="set_aside_reason" name="Set aside because" index="18"/>
    <alias field="n_scans" name="Scans seen" index="19"/>
    <alias field="contrast_day_k" name="Day contrast (K)" index="20"/>
    <alias field="contrast_night_k" name="Night contrast (K)" index="21"/>
    <alias field="mine_curve_r" name="Match with a mine's diurnal curve (-1 to 1)" index="22"/>
    <alias field="mine_curve_level" name="Offset from a mine's diurnal curve (swings)" index="23"/>
    <alias field="fix_quality" name="GNSS fix quality" index="24"/>
    <alias field="figure" name="Contrast curve" index="25"/>
    <alias field="contrast_series" name="Contrast series (JSON)" index="26"/>
    <alias field="found_by" name="Found by (scans / stack)" index="27"/>
    <alias field="short_id" name="Short id" index="28"/>
    <alias field="depth" name="Burial depth ± 1σ" index="29"/>
    <alias field="diffusivity" name="Thermal diffusivity ± 1σ" index="30"/>
    <alias field="likelihood" name="Mine likelihood" index="31"/>
    <alias field="cue_confidence_pct" name="Class cue confidence" index="32"/>
  </aliases>
  <defaults>
    <default field="anomaly_id" applyOnUpdate="0" expression=""/>
    <default field="x" applyOnUpdate="0" expression=""/>
    <default field="y" applyOnUpdate="0" expression=""/>
    <default field="lat" applyOnUpdate="0" expression=""/>
    <default field="lon" applyOnUpdate="0" expression=""/>
    <default field="area_m2" applyOnUpdate="0" expression=""/>
    <default field="diameter_m" applyOnUpdate="0" expression=""/>
    <default field="circularity" applyOnUpdate="0" expression=""/>
    <default field="depth_m" applyOnUpdate="0" expression=""/>
    <default field="depth_sigma_m" applyOnUpdate="0" expression=""/>
    <default field="diffusivity_m2s" applyOnUpdate="0" expression=""/>
    <default field="diffusivity_sigma_m2s" applyOnUpdate="0" expression=""/>
    <default field="status" applyOnUpdate="0" expression=""/>
    <default field="polarity" applyOnUpdate="0" expression=""/>
    <default field="class_cue" applyOnUpdate="0" expression=""/>
    <default field="cue_confidence" applyOnUpdate="0" expression=""/>
    <default field="p_mine" applyOnUpdate="0" expression=""/>
    <default field="priority" applyOnUpdate="0" expression=""/>
    <default field="set_aside_reason" applyOnUpdate="0" expression=""/>
    <default field="n_scans" applyOnUpdate="0" expression=""/>
    <default field="contrast_day_k" applyOnUpdate="0" expression=""/>
    <default field="contrast_night_k" applyOnUpdate="0" expression=""/>
    <default field="mine_curve_r" applyOnUpdate="0" expression=""/>
    <default field="mine_curve_level" applyOnUpdate="0" expression=""/>
    <default field="fix_quality" applyOnUpdate="0" expression=""/>
    <default field="figure" applyOnUpdate="0" expression=""/>
    <default field="contrast_series" applyOnUpdate="0" expression=""/>
    <default field="found_by" applyOnUpdate="0" expression=""/>
    <default field="short_id" applyOnUpdate="0" expression=""/>
    <default field="depth" applyOnUpdate="0" expression=""/>
    <default field="diffusivity" applyOnUpdate="0" expression=""/>
    <default field="likelihood" applyOnUpdate="0" expression=""/>
    <default field="cue_confidence_pct" applyOnUpdate="0" expression=""/>
  </defaults>
  <constraints>
    <constraint field="anomaly_id" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="x" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="y" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="lat" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="lon" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="area_m2" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="diameter_m" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="circularity" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="depth_m" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="depth_sigma_m" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="diffusivity_m2s" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="diffusivity_sigma_m2s" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="status" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="polarity" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="class_cue" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="cue_confidence" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="p_mine" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="priority" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="set_aside_reason" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="n_scans" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="contrast_day_k" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="contrast_night_k" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="mine_curve_r" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="mine_curve_level" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="fix_quality" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="figure" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="contrast_series" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="found_by" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="short_id" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="depth" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="diffusivity" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="likelihood" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
    <constraint field="cue_confidence_pct" exp_strength="0" unique_strength="0" notnull_strength="0" constraints="0"/>
  </constraints>
  <constraintExpressions>
    <constraint exp="" field="anomaly_id" desc=""/>
    <constraint exp="" field="x" desc=""/>
    <constraint exp="" field="y" desc=""/>
    <constraint exp="" field="lat" desc=""/>
    <constraint exp="" field="lon" desc=""/>
    <constraint exp="" field="area_m2" desc=""/>
    <constraint exp="" field="diameter_m" desc=""/>
    <constraint exp="" field="circularity" desc=""/>
    <constraint exp="" field="depth_m" desc=""/>
    <constraint exp="" field="depth_sigma_m" desc=""/>
    <constraint exp="" field="diffusivity_m2s" desc=""/>
    <constraint exp="" field="diffusivity_sigma_m2s" desc=""/>
    <constraint exp="" field="status" desc=""/>
    <constraint exp="" field="polarity" desc=""/>
    <constraint exp="" field="class_cue" desc=""/>
    <constraint exp="" field="cue_confidence" desc=""/>
    <constraint exp="" field="p_mine" desc=""/>
    <constraint exp="" field="priority" desc=""/>
    <constraint exp="" field="set_aside_reason" desc=""/>
    <constraint exp="" field="n_scans" desc=""/>
    <constraint exp="" field="contrast_day_k" desc=""/>
    <constraint exp="" field="contrast_night_k" desc=""/>
    <constraint exp="" field="mine_curve_r" desc=""/>
    <constraint exp="" field="mine_curve_level" desc=""/>
    <constraint exp="" field="fix_quality" desc=""/>
    <constraint exp="" field="figure" desc=""/>
    <constraint exp="" field="contrast_series" desc=""/>
    <constraint exp="" field="found_by" desc=""/>
    <constraint exp="" field="short_id" desc=""/>
    <constraint exp="" field="depth" desc=""/>
    <constraint exp="" field="diffusivity" desc=""/>
    <constraint exp="" field="likelihood" desc=""/>
    <constraint exp="" field="cue_confidence_pct" desc=""/>
  </constraintExpressions>
  <expressionfields>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="short_id" type="10" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="depth" type="10" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="diffusivity" type="10" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="likelihood" type="10" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="cue_confidence_pct" type="10" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="short_id" type="10" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="depth" type="10" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="diffusivity" type="10" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="likelihood" type="10" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="cue_confidence_pct" type="10" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="short_id" type="10" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="depth" type="10" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="diffusivity" type="10" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="likelihood" type="10" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="cue_confidence_pct" type="10" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="short_id" type="10" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="depth" type="10" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="diffusivity" type="10" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="likelihood" type="10" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="cue_confidence_pct" type="10" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="short_id" type="10" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="depth" type="10" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="diffusivity" type="10" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="likelihood" type="10" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="cue_confidence_pct" type="10" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="short_id" type="10" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="depth" type="10" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="diffusivity" type="10" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 > &quot;diffusivity_m2s&quot; * 1e6 THEN 'unconstrained' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="likelihood" type="10" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="cue_confidence_pct" type="10" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="short_id" type="10" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="depth" type="10" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="diffusivity" type="10" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 > &quot;diffusivity_m2s&quot; * 1e6 THEN 'unconstrained' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="likelihood" type="10" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="cue_confidence_pct" type="10" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="short_id" type="10" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="depth" type="10" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="diffusivity" type="10" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 > &quot;diffusivity_m2s&quot; * 1e6 THEN 'unconstrained' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="likelihood" type="10" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END"/>
    <field comment="" typeName="" precision="0" subType="0" length="0" name="cue_confidence_pct" type="10" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END"/>
  </expressionfields>
  <attributetableconfig sortExpression="coalesce(attribute('priority'), 1000000 * (CASE WHEN &quot;class_cue&quot; = 'at_mine' THEN 0 WHEN &quot;class_cue&quot; = 'ap_mine' THEN 1 WHEN &quot;class_cue&quot; = 'unknown' THEN 2 ELSE 3 END) - round(1000 * max(abs(&quot;contrast_day_k&quot;), abs(&quot;contrast_night_k&quot;))))" actionWidgetStyle="dropDown" sortOrder="0">
    <columns>
      <column hidden="0" width="-1" type="field" name="anomaly_id"/>
      <column hidden="0" width="-1" type="field" name="polarity"/>
      <column hidden="0" width="-1" type="field" name="area_m2"/>
      <column hidden="0" width="-1" type="field" name="p_mine"/>
      <column hidden="0" width="-1" type="field" name="priority"/>
      <column hidden="0" width="-1" type="field" name="cue_confidence"/>
      <column hidden="0" width="-1" type="field" name="set_aside_reason"/>
      <column hidden="0" width="-1" type="field" name="short_id"/>
      <column hidden="0" width="-1" type="field" name="depth"/>
      <column hidden="0" width="-1" type="field" name="diffusivity"/>
      <column hidden="0" width="-1" type="field" name="likelihood"/>
      <column hidden="0" width="-1" type="field" name="cue_confidence_pct"/>
      <column hidden="1" width="-1" type="actions"/>
    </columns>
  </attributetableconfig>
  <conditionalstyles>
    <rowstyles/>
    <fieldstyles/>
  </conditionalstyles>
  <storedexpressions/>
  <editform tolerant="1"></editform>
  <editforminit/>
  <editforminitcodesource>0</editforminitcodesource>
  <editforminitfilepath></editforminitfilepath>
  <editforminitcode><![CDATA[]]></editforminitcode>
  <featformsuppress>0</featformsuppress>
  <editorlayout>tablayout</editorlayout>
  <attributeEditorForm>
    <attributeEditorContainer groupBox="0" showLabel="1" visibilityExpressionEnabled="0" columnCount="1" name="Suspect" visibilityExpression="">
      <attributeEditorContainer groupBox="1" showLabel="1" visibilityExpressionEnabled="0" columnCount="1" name="Identification" visibilityExpression="">
        <attributeEditorField showLabel="1" name="short_id" index="28"/>
        <attributeEditorField showLabel="1" name="anomaly_id" index="0"/>
        <attributeEditorField showLabel="1" name="priority" index="17"/>
        <attributeEditorField showLabel="1" name="class_cue" index="14"/>
        <attributeEditorField showLabel="1" name="likelihood" index="31"/>
        <attributeEditorField showLabel="1" name="cue_confidence_pct" index="32"/>
        <attributeEditorField showLabel="1" name="status" index="12"/>
        <attributeEditorField showLabel="1" name="found_by" index="27"/>
        <attributeEditorField showLabel="1" name="polarity" index="13"/>
        <attributeEditorField showLabel="1" name="set_aside_reason" index="18"/>
      </attributeEditorContainer>
      <attributeEditorContainer groupBox="1" showLabel="1" visibilityExpressionEnabled="0" columnCount="1" name="Burial depth and soil" visibilityExpression="">
        <attributeEditorField showLabel="1" name="depth" index="29"/>
        <attributeEditorField showLabel="1" name="diffusivity" index="30"/>
      </attributeEditorContainer>
      <attributeEditorContainer groupBox="1" showLabel="1" visibilityExpressionEnabled="0" columnCount="1" name="Thermal contrast" visibilityExpression="">
        <attributeEditorField showLabel="1" name="contrast_day_k" index="20"/>
        <attributeEditorField showLabel="1" name="contrast_night_k" index="21"/>
        <attributeEditorField showLabel="1" name="mine_curve_r" index="22"/>
        <attributeEditorField showLabel="1" name="mine_curve_level" index="23"/>
        <attributeEditorField showLabel="1" name="n_scans" index="19"/>
      </attributeEditorContainer>
      <attributeEditorContainer groupBox="1" showLabel="1" visibilityExpressionEnabled="0" columnCount="1" name="Shape" visibilityExpression="">
        <attributeEditorField showLabel="1" name="diameter_m" index="6"/>
        <attributeEditorField showLabel="1" name="area_m2" index="5"/>
        <attributeEditorField showLabel="1" name="circularity" index="7"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer groupBox="0" showLabel="1" visibilityExpressionEnabled="0" columnCount="1" name="Contrast curve" visibilityExpression="">
      <attributeEditorContainer groupBox="1" showLabel="1" visibilityExpressionEnabled="0" columnCount="1" name="Contrast curve" visibilityExpression="">
        <attributeEditorField showLabel="1" name="figure" index="25"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer groupBox="0" showLabel="1" visibilityExpressionEnabled="0" columnCount="1" name="Position" visibilityExpression="">
      <attributeEditorContainer groupBox="1" showLabel="1" visibilityExpressionEnabled="0" columnCount="1" name="Position" visibilityExpression="">
        <attributeEditorField showLabel="1" name="x" index="1"/>
        <attributeEditorField showLabel="1" name="y" index="2"/>
        <attributeEditorField showLabel="1" name="lat" index="3"/>
        <attributeEditorField showLabel="1" name="lon" index="4"/>
        <attributeEditorField showLabel="1" name="fix_quality" index="24"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer groupBox="0" showLabel="1" visibilityExpressionEnabled="0" columnCount="1" name="Stored values" visibilityExpression="">
      <attributeEditorContainer groupBox="1" showLabel="1" visibilityExpressionEnabled="0" columnCount="1" name="Stored values" visibilityExpression="">
        <attributeEditorField showLabel="1" name="depth_m" index="8"/>
        <attributeEditorField showLabel="1" name="depth_sigma_m" index="9"/>
        <attributeEditorField showLabel="1" name="diffusivity_m2s" index="10"/>
        <attributeEditorField showLabel="1" name="diffusivity_sigma_m2s" index="11"/>
        <attributeEditorField showLabel="1" name="p_mine" index="16"/>
        <attributeEditorField showLabel="1" name="cue_confidence" index="15"/>
        <attributeEditorField showLabel="1" name="contrast_series" index="26"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
  </attributeEditorForm>
  <editable/>
  <labelOnTop/>
  <reuseLastValue/>
  <dataDefinedFieldProperties/>
  <widgets/>
  <mapTip>&lt;b>[% "short_id" %]&lt;/b> [% "class_cue" %] ([% "status" %])&lt;br/>depth [% "depth" %]&lt;br/>diffusivity [% "diffusivity" %]</mapTip>
  <layerGeometryType>2</layerGeometryType>
</qgis>
